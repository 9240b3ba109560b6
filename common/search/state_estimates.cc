#include "search/state_estimates.h"

namespace envdesign::search {

StateEstimates::~StateEstimates() = default;

} // namespace envdesign::search
