// A main() for the fuzz targets where libFuzzer is not linked (GCC builds):
// it runs the target once on every file named, and on every file under every
// folder named, so the seed corpora and the project's scenes run as ordinary
// regression tests under CTest. Each input runs in its own folder, so that
// the includes and models a scene names relative to itself are found (the
// targets resolve paths from "."). Prints how many inputs ran.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

void run_file(const std::filesystem::path& relative) {
    const std::filesystem::path file = std::filesystem::absolute(relative);
    std::filesystem::current_path(file.parent_path());
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
    long inputs = 0;
    std::vector<std::filesystem::path> paths;  // absolute: the inputs change the working folder
    for (int i = 1; i < argc; ++i) paths.push_back(std::filesystem::absolute(argv[i]));
    for (const std::filesystem::path& path : paths) {
        if (std::filesystem::is_directory(path)) {
            for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
                if (!entry.is_regular_file()) continue;
                run_file(entry.path());
                ++inputs;
            }
        } else if (std::filesystem::is_regular_file(path)) {
            run_file(path);
            ++inputs;
        } else {
            std::fprintf(stderr, "corpus_driver: no such file or folder: %s\n", path.c_str());
            return 1;
        }
    }
    std::printf("corpus_driver: %ld inputs ran\n", inputs);
    return inputs > 0 ? 0 : 1;
}
