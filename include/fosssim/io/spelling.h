// "Did you mean ...?" for misspelt names: element and attribute names in the loader, options on
// the command line. Not part of the installed package (cmake/FosssimPackage.cmake lists those).
#pragma once

#include <string>
#include <vector>

namespace fosssim::io {

/// The candidate closest to `word` when it is a plausible misspelling of it: the same name in
/// another case, or within an edit distance (insertions, deletions, substitutions and swaps of
/// neighbours) of 1 for names of up to 4 letters and 2 for longer ones. Empty when none is close
/// (or when two candidates are equally close: a guess between two would mislead).
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);

/// The optimal-string-alignment distance between a and b (case-sensitive).
int editDistance(const std::string& a, const std::string& b);

}  // namespace fosssim::io
