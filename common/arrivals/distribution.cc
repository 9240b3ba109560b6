#include "arrivals/distribution.h"

#include <cassert>
#include <cmath>
#include <cstdio>

namespace envdesign::arrivals {

double total_variation(const Distribution &p, const Distribution &q) {
    // Merge the two sorted maps: tasks in only one of them count with 0 in the other.
    double sum = 0;
    auto a = p.begin(), b = q.begin();
    while (a != p.end() || b != q.end()) {
        if (b == q.end() || (a != p.end() && a->first < b->first)) {
            sum += std::abs(a->second);
            ++a;
        } else if (a == p.end() || b->first < a->first) {
            sum += std::abs(b->second);
            ++b;
        } else {
            sum += std::abs(a->second - b->second);
            ++a;
            ++b;
        }
    }
    return sum / 2;
}

Distribution normalized(const Distribution &weights) {
    double total = 0;
    for (const auto &[task, w] : weights) {
        assert(w >= 0);
        total += w;
    }
    Distribution out;
    if (!(total > 0))
        return out;
    for (const auto &[task, w] : weights)
        out[task] = w / total;
    return out;
}

std::string to_string(const Distribution &d) {
    std::string out = "{";
    for (const auto &[task, p] : d) {
        char number[32];
        std::snprintf(number, sizeof number, "%.4g", p);
        out += (out.size() > 1 ? ", " : "") + task + ": " + number;
    }
    return out + "}";
}

} // namespace envdesign::arrivals
