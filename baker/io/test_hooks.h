// baker/io/test_hooks.h: pause points a test sets through the environment, so that it can
// interrupt a bake at an exact moment instead of guessing one from timing or terminal output.
#pragma once
#include <cstddef>
#include <string>

namespace kiln {

/// KILN_TEST_PAUSE_AFTER_TEXELS=N (N >= 1): the number of texels after which a bake pauses, or 0
/// when the variable is unset or not a positive integer. Read once per process; the bake's only
/// cost when it is unset is one comparison per texel.
std::size_t TestPauseAfterTexels();

/// KILN_TEST_PAUSE_BEFORE_RENAME=NAME: true when an atomic write whose destination's file name is
/// `fileName` must pause once its temporary file is complete, before it is renamed (for a table,
/// before the folder lock is taken; for manifest.json, while it is held). Read once per process;
/// false for every name when the variable is unset.
bool TestPauseBeforeRename(const std::string& fileName);

/// With KILN_TEST_NOTES set (read once): writes "kiln: test note: <what>\n" to stderr (one
/// write(2)), so a test learns that the process reached a point (e.g. it waits for a lock).
/// Without it: nothing.
void TestNote(const std::string& what);

/// Writes "kiln: test pause: <what>\n" to stderr (one write(2), unbuffered) and then blocks
/// until SIGUSR1 resumes it (it then returns) or another signal ends the process. Only called
/// when a test asked for it; installs its SIGUSR1 handler then.
void TestPause(const std::string& what);

}  // namespace kiln
