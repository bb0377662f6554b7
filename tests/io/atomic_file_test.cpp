// AtomicFile: where the temporary lives, what happens on commit, on
// abandonment and on failure.
#include "zeroset/io/atomic_file.hpp"
#include "zeroset/io/pending_files.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include <sys/resource.h>

#include "support/temp_dir.hpp"

namespace zeroset {
namespace {

using Names = std::vector<std::string>;
using Bytes = std::vector<std::uint8_t>;

TEST(AtomicFile, TemporaryIsHiddenBesideTheTargetUntilCommit) {
    const test::TempDir dir;
    const Bytes content{'n', 'e', 'w'};
    {
        AtomicFile file(dir / "out.bin");
        EXPECT_EQ(file.target(), dir / "out.bin");
        EXPECT_EQ(file.temp_path().parent_path(), dir.path());
        const std::string temp_name = file.temp_path().filename().string();
        EXPECT_EQ(temp_name.rfind(".out.bin.tmp-", 0), 0u) << temp_name;
        EXPECT_EQ(dir.entries(), Names{temp_name});

        file.write(content);
        EXPECT_FALSE(std::filesystem::exists(dir / "out.bin"));
        file.commit();
    }
    EXPECT_EQ(dir.entries(), Names{"out.bin"});
    EXPECT_EQ(test::read_bytes(dir / "out.bin"), content);
}

TEST(AtomicFile, AbandonedWriteLeavesTheTargetAlone) {
    const test::TempDir dir;
    test::write_text(dir / "out.bin", "old");
    {
        AtomicFile file(dir / "out.bin");
        file.write(Bytes(1000, 7));
    }  // destroyed without commit()
    EXPECT_EQ(dir.entries(), Names{"out.bin"});
    EXPECT_EQ(test::read_bytes(dir / "out.bin"), (Bytes{'o', 'l', 'd'}));
}

TEST(AtomicFile, ConcurrentWritersGetDistinctTemporaries) {
    const test::TempDir dir;
    AtomicFile first(dir / "out.bin");
    AtomicFile second(dir / "out.bin");
    EXPECT_NE(first.temp_path(), second.temp_path());
    first.write(Bytes{1});
    second.write(Bytes{2, 2});
    first.commit();
    second.commit();  // last commit wins, whole
    EXPECT_EQ(test::read_bytes(dir / "out.bin"), (Bytes{2, 2}));
    EXPECT_EQ(dir.entries(), Names{"out.bin"});
}

TEST(AtomicFile, WritesLargeAndEmptyFiles) {
    const test::TempDir dir;
    Bytes large(3'000'000);
    for (std::size_t i = 0; i < large.size(); ++i) large[i] = static_cast<std::uint8_t>(i * 31 + i / 977);
    write_file_atomically(dir / "large.bin", large);
    EXPECT_EQ(test::read_bytes(dir / "large.bin"), large);
    write_file_atomically(dir / "empty.bin", {});
    EXPECT_EQ(std::filesystem::file_size(dir / "empty.bin"), 0u);
    EXPECT_EQ(dir.entries(), (Names{"empty.bin", "large.bin"}));
}

TEST(AtomicFile, ErrorsNameTheTarget) {
    const test::TempDir dir;
    try {
        AtomicFile file(dir / "missing" / "out.bin");
        FAIL();
    } catch (const FileWriteError& e) {
        EXPECT_EQ(e.path(), dir / "missing" / "out.bin");
        EXPECT_EQ(e.reason(), "cannot create file: No such file or directory");
    }
    EXPECT_THROW(AtomicFile(dir.path() / ""), FileWriteError);  // no file name
    EXPECT_EQ(dir.entries(), Names{});
}

TEST(AtomicFile, UseAfterCommitThrows) {
    const test::TempDir dir;
    AtomicFile file(dir / "out.bin");
    file.commit();
    EXPECT_THROW(file.write(Bytes{1}), FileWriteError);
    EXPECT_THROW(file.commit(), FileWriteError);
    EXPECT_EQ(dir.entries(), Names{"out.bin"});
}

// Lowers RLIMIT_FSIZE for one scope so that write() fails with EFBIG, the
// way a full disk fails with ENOSPC (SIGXFSZ is ignored meanwhile).
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        ::getrlimit(RLIMIT_FSIZE, &old_);
        rlimit limited = old_;
        limited.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &limited);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, old_handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit old_{};
    void (*old_handler_)(int) = nullptr;
};

TEST(AtomicFile, WriteFailureIsReportedAndCleanedUp) {
    const test::TempDir dir;
    test::write_text(dir / "out.bin", "old");
    try {
        const FileSizeLimit limit(4096);
        write_file_atomically(dir / "out.bin", Bytes(100'000, 1));
        FAIL() << "a write past RLIMIT_FSIZE succeeded";
    } catch (const FileWriteError& e) {
        EXPECT_EQ(e.reason(), "cannot write file: File too large");
    }
    EXPECT_EQ(dir.entries(), Names{"out.bin"});
    EXPECT_EQ(test::read_bytes(dir / "out.bin"), (Bytes{'o', 'l', 'd'}));
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

// What the program's signal handler does (apps/zeroset/interrupts.cpp): the
// temporary file of a write in progress is removed, and nothing else.
TEST(AtomicFile, ASignalHandlerCanRemoveTheTemporaryFileOfAWriteInProgress) {
    const test::TempDir dir;
    const auto keep = dir.write("keep.txt", "untouched");
    AtomicFile file(dir.path() / "out.png");
    file.write(std::vector<std::uint8_t>(100, 7));
    ASSERT_TRUE(std::filesystem::exists(file.temp_path()));
    remove_pending_files();
    EXPECT_FALSE(std::filesystem::exists(file.temp_path()));
    EXPECT_TRUE(std::filesystem::exists(keep));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png"));
}

TEST(AtomicFile, ACommittedFileIsNoLongerPending) {
    const test::TempDir dir;
    write_file_atomically(dir.path() / "done.txt", std::vector<std::uint8_t>{'o', 'k'});
    remove_pending_files();
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "done.txt"));
}

}  // namespace
}  // namespace zeroset
