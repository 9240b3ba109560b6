#pragma once
// The warnings of `envdesign design` on stderr, as "warning: ..." lines (the JSON result
// carries them as "warnings": [...], design_run.h says which): a spec the reader accepted but
// may not mean (probabilities not summing to 1, two problems of a task with different goals),
// and tasks unsolvable in the unmodified models, each with the reason (so that
// `objective: inf` comes with a word why).

#include <string>
#include <vector>

namespace envdesign::cli {

// Prints each on stderr, prefixed "warning: " unless it already names its place.
void print_warnings(const std::vector<std::string> &warnings);

} // namespace envdesign::cli
