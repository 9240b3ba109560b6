#pragma once
// A planner's memory: what one job's search may hold, and when the process as a whole is
// near its limit (Planner::guard_memory), read from the process's resident size.

#include <cstddef>

namespace envdesign::cluster {

// Room kept for what a search's byte count misses: the heuristic's own data, a plan being
// built, the allocator's slack.
inline constexpr std::size_t JOB_MEMORY_MARGIN = std::size_t{8} << 20;

// The process's resident memory (/proc/self/statm); 0 where it cannot be read.
std::size_t resident_bytes();

// The search data one job may hold: `job_memory_bytes` less the process's `resident` bytes
// shared over `workers`, less JOB_MEMORY_MARGIN; at least 1 byte (0 would be "no limit").
std::size_t job_search_budget(std::size_t job_memory_bytes, std::size_t resident, int workers);

// Whether running jobs must stop: `resident` is past the `idle` size plus two thirds of the
// room to `limit` less JOB_MEMORY_MARGIN. A search grows in steps (a vector or hash table
// doubling copies at once), measured up to 40% of what it held, so its last step still fits.
bool past_memory_guard(std::size_t resident, std::size_t idle, std::size_t limit);

} // namespace envdesign::cluster
