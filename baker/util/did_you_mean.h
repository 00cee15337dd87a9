// "Did you mean ...?": the known name closest to a mistyped one, for error messages (unknown
// tables, models, options and subcommands).
#pragma once
#include <string>
#include <vector>

namespace kiln {

/// The Damerau-Levenshtein distance of `a` and `b` in its optimal-string-alignment form: the
/// fewest insertions, deletions, substitutions and swaps of two adjacent characters (each 1)
/// that turn `a` into `b`, no substring edited twice. Case-sensitive, byte by byte.
int EditDistance(const std::string& a, const std::string& b);

/// The candidate closest to `word` by EditDistance when it is close enough to be a typo: at
/// most max(1, min(3, size / 3)) edits, `size` the length of `word` (so "ggx-dgf" -> "ggx-dfg",
/// and not every two-letter word to every other). The first candidate wins a tie; "" when none is
/// close enough or `word` is a candidate.
std::string ClosestName(const std::string& word, const std::vector<std::string>& candidates);

/// " (did you mean 'NAME'?)" with NAME = ClosestName(word, candidates), or "" when there is none:
/// to append to "unknown ... 'word'".
std::string DidYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace kiln
