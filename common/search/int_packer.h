#pragma once
// Packs variables with small finite ranges into arrays of 32-bit bins, like Fast
// Downward's IntPacker. A variable with range r (values 0..r-1) takes ceil(log2(r)) bits and
// never straddles two bins; variables are placed first-fit-decreasing by bit width, so the
// number of bins per state is small.
//
// Example:
//   IntPacker packer({3, 2, 5});          // 2 + 1 + 3 bits -> one bin
//   std::vector<IntPacker::Bin> bins(packer.num_bins());
//   packer.set(bins.data(), 2, 4);
//   int v = packer.get(bins.data(), 2);  // 4

#include <cstdint>
#include <vector>

namespace envdesign::search {

class IntPacker {
public:
    using Bin = std::uint32_t;
    static constexpr int BITS_PER_BIN = 32;

    // ranges[i] >= 1 is the number of values of variable i.
    explicit IntPacker(const std::vector<int> &ranges);

    int num_bins() const { return num_bins_; }
    int num_variables() const { return static_cast<int>(variables_.size()); }
    int bits(int var) const { return variables_[var].bits; }

    int get(const Bin *buffer, int var) const {
        const VariableInfo &info = variables_[var];
        return static_cast<int>((buffer[info.bin] >> info.shift) & info.mask);
    }
    void set(Bin *buffer, int var, int value) const {
        const VariableInfo &info = variables_[var];
        Bin &bin = buffer[info.bin];
        bin = (bin & ~(info.mask << info.shift)) | (static_cast<Bin>(value) << info.shift);
    }

private:
    struct VariableInfo {
        int bin = 0;
        int shift = 0;
        int bits = 0;
        Bin mask = 0; // `bits` low bits set
    };

    std::vector<VariableInfo> variables_;
    int num_bins_ = 0;
};

} // namespace envdesign::search
