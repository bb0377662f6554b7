// AtomicFile on POSIX: open(O_EXCL) for a temporary name nobody else holds,
// write() in a loop, fsync() and close() with their errors checked (a full
// disk may only show up there), then rename(), which replaces atomically.
#include "zeroset/io/atomic_file.hpp"

#include "zeroset/io/pending_files.hpp"

#include <atomic>
#include <cerrno>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace zeroset {

namespace {

std::string errno_message(int error_number) { return std::generic_category().message(error_number); }

// ".<name>.tmp-<pid>-<counter>" beside the target: hidden, and on the same
// file system, so rename() can replace the target atomically.
std::filesystem::path temp_name_for(const std::filesystem::path& target, unsigned counter) {
    std::string name = ".";
    name += target.filename().string();
    name += ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-" + std::to_string(counter);
    return target.parent_path() / name;
}

std::atomic<unsigned> temp_counter{0};

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    if (!target_.has_filename()) throw FileWriteError(target_, "not a file name");
    for (int attempt = 0; attempt < 100; ++attempt) {
        temp_ = temp_name_for(target_, temp_counter.fetch_add(1, std::memory_order_relaxed));
        // Registered before it exists, so a signal can never leave it behind.
        pending_slot_ = register_pending_file(temp_);
        fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd_ >= 0) return;
        const int error_number = errno;
        unregister_pending_file(pending_slot_);  // not ours: it may be another writer's
        pending_slot_ = -1;
        if (error_number != EEXIST) {  // EEXIST: a stale temporary holds the name; try the next
            temp_.clear();
            throw FileWriteError(target_, "cannot create file: " + errno_message(error_number));
        }
    }
    const int error_number = errno;
    temp_.clear();
    throw FileWriteError(target_, "cannot create file: " + errno_message(error_number));
}

AtomicFile::~AtomicFile() {
    if (!committed_) discard();
}

void AtomicFile::write(std::span<const std::uint8_t> bytes) {
    if (fd_ < 0) throw FileWriteError(target_, "write after commit or failure");
    const std::uint8_t* data = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ::ssize_t n = ::write(fd_, data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot write file", errno);
        }
        data += n;
        left -= static_cast<std::size_t>(n);
    }
}

void AtomicFile::commit() {
    if (fd_ < 0) throw FileWriteError(target_, "commit after commit or failure");
    if (::fsync(fd_) != 0) fail("cannot write file", errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("cannot write file", errno);
    std::error_code error;
    std::filesystem::rename(temp_, target_, error);
    if (error) {
        discard();
        throw FileWriteError(target_, "cannot replace file: " + error.message());
    }
    unregister_pending_file(pending_slot_);
    pending_slot_ = -1;
    committed_ = true;
}

void AtomicFile::fail(const std::string& what, int error_number) {
    discard();
    throw FileWriteError(target_, what + ": " + errno_message(error_number));
}

void AtomicFile::discard() noexcept {
    if (fd_ >= 0) {
        ::close(fd_);
        fd_ = -1;
    }
    if (!temp_.empty()) {
        std::error_code ignored;
        std::filesystem::remove(temp_, ignored);
        temp_.clear();
    }
    unregister_pending_file(pending_slot_);
    pending_slot_ = -1;
}

void write_file_atomically(const std::filesystem::path& target, std::span<const std::uint8_t> bytes) {
    AtomicFile file(target);
    file.write(bytes);
    file.commit();
}

}  // namespace zeroset
