// A test fixture that runs the zeroset program (ZEROSET_BINARY) in a fresh
// directory, capturing its exit status, stdout and stderr outside it — so a
// test can also check that a failure left no file behind.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/temp_dir.hpp"

namespace zeroset::test {

inline std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

struct Outcome {
    int status;
    std::string out;
    std::string err;
};

class CliTest : public ::testing::Test {
protected:
    /// Runs `zeroset ARGS` in dir_.
    Outcome run(const std::string& args) const { return run_shell("'" ZEROSET_BINARY "' " + args); }

    /// Runs a shell command line in dir_ (for what a test must do around the
    /// program, such as signalling it).
    Outcome run_shell(const std::string& command_line) const {
        const std::filesystem::path out = logs_ / "stdout.txt", err = logs_ / "stderr.txt";
        const std::string command = "cd '" + dir_.path().string() + "' && { " + command_line + "; } > '" +
                                    out.string() + "' 2> '" + err.string() + "'";
        const int raw = std::system(command.c_str());
        return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
    }

    TempDir dir_;   // where the program runs
    TempDir logs_;  // its captured output
};

}  // namespace zeroset::test
