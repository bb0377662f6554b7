// A progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <chrono>

namespace zeroset::cli {

class ProgressBar {
public:
    ProgressBar();
    [[nodiscard]] bool enabled() const { return enabled_; }
    /// Redraws the bar (at most a few times a second) for done of total,
    /// after the label.
    void update(int done, int total, const char* label = "rendering");
    /// Erases the bar's line.
    void finish();

private:
    bool enabled_;
    std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace zeroset::cli
