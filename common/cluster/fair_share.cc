#include "cluster/fair_share.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace envdesign::cluster {

void FairShare::add_service(std::uint64_t client, double seconds) {
    service_[client] += seconds;
    if (service_.size() <= MAX_CLIENTS)
        return;
    auto least = service_.end();
    for (auto it = service_.begin(); it != service_.end(); ++it)
        if (it->first != client && (least == service_.end() || it->second < least->second))
            least = it;
    service_.erase(least);
}

FairShare::Key FairShare::key(std::uint64_t client, const Held &held) const {
    auto h = held.find(client);
    auto s = service_.find(client);
    return {h == held.end() ? 0 : h->second, s == service_.end() ? 0.0 : s->second};
}

std::size_t FairShare::next(const std::vector<std::uint64_t> &queued, const Held &held) const {
    std::size_t best = 0;
    Key best_key = key(queued[0], held);
    for (std::size_t i = 1; i < queued.size(); ++i) {
        Key k = key(queued[i], held);
        if (k < best_key)
            best = i, best_key = k;
    }
    return best;
}

int FairShare::share(const std::vector<std::uint64_t> &queued, const std::vector<Running> &running,
                     int slots) {
    std::set<std::uint64_t> clients(queued.begin(), queued.end());
    for (const Running &r : running)
        clients.insert(r.client);
    return std::max(1, slots / static_cast<int>(std::max<std::size_t>(1, clients.size())));
}

std::optional<std::int64_t> FairShare::victim(const std::vector<std::uint64_t> &queued,
                                              const std::vector<Running> &running, const Held &held,
                                              int slots) const {
    int fair = share(queued, running, slots);
    if (std::none_of(queued.begin(), queued.end(),
                     [&](std::uint64_t c) { return key(c, held).held < fair; }))
        return std::nullopt;
    // Over their share: the longest-running job (it holds a worker) of the client holding most.
    const Running *chosen = nullptr;
    Key chosen_key{0, 0};
    for (const Running &r : running) {
        Key k = key(r.client, held);
        if (k.held <= fair)
            continue;
        if (!chosen || chosen_key < k || (!(k < chosen_key) && r.seconds > chosen->seconds))
            chosen = &r, chosen_key = k;
    }
    if (chosen)
        return chosen->job;
    return turn(queued, running, held);
}

// Every client at its share: a client holding none takes a turn from a job past its quantum.
std::optional<std::int64_t> FairShare::turn(const std::vector<std::uint64_t> &queued,
                                            const std::vector<Running> &running,
                                            const Held &held) const {
    if (std::none_of(queued.begin(), queued.end(),
                     [&](std::uint64_t c) { return key(c, held).held == 0; }))
        return std::nullopt;
    const Running *chosen = nullptr;
    Key chosen_key{0, 0};
    for (const Running &r : running) {
        if (r.seconds <= quantum_s_ * std::ldexp(1.0, std::min(r.preemptions, 20)))
            continue; // within its quantum
        Key k = key(r.client, held);
        bool better = !chosen || chosen_key < k ||
                      (!(k < chosen_key) && r.seconds < chosen->seconds); // youngest: least lost
        if (better)
            chosen = &r, chosen_key = k;
    }
    if (!chosen)
        return std::nullopt;
    return chosen->job;
}

} // namespace envdesign::cluster
