// The handler does only async-signal-safe things: unlink(), write(), then
// the default action of the signal, so the exit status says what ended it.
#include "interrupts.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstring>

#include "zeroset/io/pending_files.hpp"

namespace zeroset::cli {

namespace {

/// What the handler says for SIGTERM and SIGHUP (null: nothing).
const char* volatile termination_message = "\nzeroset: terminated; nothing was written\n";

void on_signal(int signal_number) {
    remove_pending_files();
    const char* what = signal_number == SIGINT ? "\nzeroset: interrupted; nothing was written\n" : termination_message;
    if (what) {
        [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, what, std::strlen(what));
    }
    ::signal(signal_number, SIG_DFL);
    ::raise(signal_number);
}

}  // namespace

void handle_interrupts() {
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction action{};
        action.sa_handler = on_signal;
        sigemptyset(&action.sa_mask);
        action.sa_flags = 0;
        ::sigaction(signal_number, &action, nullptr);
    }
}

void explain_termination_as_rank(int rank) {
    termination_message = rank == 0 ? "\nzeroset: stopped by mpirun, which ends the job when a rank fails (it names "
                                      "the rank); nothing was written\n"
                                    : nullptr;
}

}  // namespace zeroset::cli
