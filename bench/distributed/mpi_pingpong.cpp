// The local MPI's message latency and bandwidth, as the distributed render's
// scaling model needs them (bench/distributed/simulate.py): ranks 0 and 1
// bounce messages of growing size; prints one line per size, then the fitted
// latency (µs) and bandwidth (MB/s). Run: mpirun -n 2 mpi_pingpong
#include <mpi.h>

#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size != 2) {
        if (rank == 0) std::fprintf(stderr, "mpi_pingpong: run it on 2 ranks (mpirun -n 2)\n");
        MPI_Finalize();
        return 2;
    }
    // A 16×16 tile with layers is 256 · (12 + 4 + 12) bytes plus a header.
    const int sizes[] = {8, 64, 512, 3200, 7300, 65536, 1 << 20};
    std::vector<char> buffer(1 << 20);
    double small_time = 0.0, large_time = 0.0;
    for (const int bytes : sizes) {
        const int rounds = bytes > 100000 ? 200 : 5000;
        for (int warm = 0; warm < 2; ++warm) {
            MPI_Barrier(MPI_COMM_WORLD);
            const double start = MPI_Wtime();
            for (int i = 0; i < rounds; ++i) {
                if (rank == 0) {
                    MPI_Send(buffer.data(), bytes, MPI_BYTE, 1, 0, MPI_COMM_WORLD);
                    MPI_Recv(buffer.data(), bytes, MPI_BYTE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                } else {
                    MPI_Recv(buffer.data(), bytes, MPI_BYTE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                    MPI_Send(buffer.data(), bytes, MPI_BYTE, 0, 0, MPI_COMM_WORLD);
                }
            }
            const double one_way = (MPI_Wtime() - start) / (2.0 * rounds);
            if (warm == 0) continue;
            if (rank == 0) std::printf("%8d bytes: %8.2f us one way\n", bytes, one_way * 1e6);
            if (bytes == sizes[0]) small_time = one_way;
            if (bytes == (1 << 20)) large_time = one_way;
        }
    }
    if (rank == 0)
        std::printf("latency_us %.3f\nbandwidth_MBps %.1f\n", small_time * 1e6,
                    ((1 << 20) - sizes[0]) / (large_time - small_time) / 1e6);
    MPI_Finalize();
    return 0;
}
