// A fixed table of paths, each slot claimed by compare-and-swap and
// published with a release store, read by the handler with acquire loads.
#include "zeroset/io/pending_files.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <climits>
#include <cstring>

namespace zeroset {

namespace {

constexpr int slot_count = 16;

enum : int { free_slot = 0, claimed = 1, ready = 2 };

struct Slot {
    std::atomic<int> state{free_slot};
    char path[PATH_MAX];
};

std::array<Slot, slot_count> slots;

}  // namespace

int register_pending_file(const std::filesystem::path& path) {
    const std::string& text = path.native();
    if (text.size() >= PATH_MAX) return -1;
    for (int i = 0; i < slot_count; ++i) {
        Slot& s = slots[static_cast<std::size_t>(i)];
        int expected = free_slot;
        if (!s.state.compare_exchange_strong(expected, claimed, std::memory_order_acquire)) continue;
        std::memcpy(s.path, text.c_str(), text.size() + 1);
        s.state.store(ready, std::memory_order_release);
        return i;
    }
    return -1;
}

void unregister_pending_file(int slot) {
    if (slot < 0 || slot >= slot_count) return;
    slots[static_cast<std::size_t>(slot)].state.store(free_slot, std::memory_order_release);
}

void remove_pending_files() noexcept {
    for (Slot& s : slots)
        if (s.state.load(std::memory_order_acquire) == ready) ::unlink(s.path);
}

}  // namespace zeroset
