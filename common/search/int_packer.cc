#include "search/int_packer.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace envdesign::search {
namespace {

int bits_for_range(int range) {
    if (range < 1)
        throw std::invalid_argument("IntPacker: a variable needs at least one value");
    int bits = 0;
    while ((static_cast<long long>(1) << bits) < range)
        ++bits;
    return bits;
}

} // namespace

IntPacker::IntPacker(const std::vector<int> &ranges) : variables_(ranges.size()) {
    std::vector<int> order(ranges.size());
    std::iota(order.begin(), order.end(), 0);
    for (std::size_t var = 0; var < ranges.size(); ++var) {
        int bits = bits_for_range(ranges[var]);
        if (bits > BITS_PER_BIN)
            throw std::invalid_argument("IntPacker: a variable needs more than 32 bits");
        variables_[var].bits = bits;
        variables_[var].mask = bits == BITS_PER_BIN ? ~Bin(0) : (Bin(1) << bits) - 1;
    }
    // First-fit decreasing; the stable sort keeps equal widths in variable order.
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return variables_[a].bits > variables_[b].bits; });
    std::vector<int> used_bits;
    for (int var : order) {
        VariableInfo &info = variables_[var];
        if (info.bits == 0)
            continue; // a constant: bin 0, shift 0, mask 0
        std::size_t bin = 0;
        while (bin < used_bits.size() && used_bits[bin] + info.bits > BITS_PER_BIN)
            ++bin;
        if (bin == used_bits.size())
            used_bits.push_back(0);
        info.bin = static_cast<int>(bin);
        info.shift = used_bits[bin];
        used_bits[bin] += info.bits;
    }
    // Even all-constant variables get a bin, so that a buffer is never empty.
    num_bins_ = std::max<int>(static_cast<int>(used_bits.size()), ranges.empty() ? 0 : 1);
}

} // namespace envdesign::search
