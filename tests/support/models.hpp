// The shared models (fidget's .vm files in ../shared/models, beside the
// repository) are not part of it: a test that needs one skips, saying so,
// when the folder is not there — a fresh clone alone still passes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

/// In a test's body: skip it unless the shared model `name` (e.g. "bear.vm") exists.
#define ZEROSET_SKIP_WITHOUT_MODEL(name)                                                        \
    if (!std::filesystem::exists(std::filesystem::path(ZEROSET_MODELS_DIR) / (name)))          \
    GTEST_SKIP() << ZEROSET_MODELS_DIR "/" << (name)                                           \
                 << " is not there (the shared models folder beside the repository)"
