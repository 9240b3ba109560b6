#include "cluster/planner_memory.h"

#include <algorithm>
#include <fstream>
#include <unistd.h>

namespace envdesign::cluster {

std::size_t resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0, resident = 0;
    if (!(statm >> pages >> resident))
        return 0;
    return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

std::size_t job_search_budget(std::size_t job_memory_bytes, std::size_t resident, int workers) {
    std::size_t taken =
        resident / static_cast<std::size_t>(std::max(1, workers)) + JOB_MEMORY_MARGIN;
    // Never 0 (that is "no limit"): a budget the process leaves no room for stops at once.
    return job_memory_bytes > taken ? job_memory_bytes - taken : 1;
}

bool past_memory_guard(std::size_t resident, std::size_t idle, std::size_t limit) {
    std::size_t room = limit > idle + JOB_MEMORY_MARGIN ? limit - idle - JOB_MEMORY_MARGIN : 0;
    return resident >= idle + room / 3 * 2;
}

} // namespace envdesign::cluster
