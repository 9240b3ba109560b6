#include "cluster/fair_share.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace envdesign::cluster {

double FairShare::decayed(const Used &used, Clock::time_point now) const {
    double age = std::max(0.0, std::chrono::duration<double>(now - used.at).count());
    return used.usage * std::exp2(-age / half_life_s_);
}

void FairShare::add_service(std::uint64_t client, double seconds, Clock::time_point now) {
    Used &used = used_[client];
    used = {decayed(used, now) + seconds, now};
    if (used_.size() <= MAX_CLIENTS)
        return;
    auto least = used_.end();
    double least_usage = 0;
    for (auto it = used_.begin(); it != used_.end(); ++it) {
        double u = decayed(it->second, now);
        if (it->first != client && (least == used_.end() || u < least_usage))
            least = it, least_usage = u;
    }
    used_.erase(least);
}

double FairShare::usage(std::uint64_t client, const std::vector<Running> &running,
                        Clock::time_point now) const {
    auto it = used_.find(client);
    double u = it == used_.end() ? 0.0 : decayed(it->second, now);
    for (const Running &r : running)
        if (r.client == client)
            u += r.seconds;
    return u;
}

std::map<std::uint64_t, FairShare::Client> FairShare::clients(const View &view) const {
    std::map<std::uint64_t, Client> all;
    for (std::uint64_t c : view.queued)
        ++all[c].waiting;
    for (const Running &r : view.running)
        ++all[r.client].held;
    for (const auto &[c, n] : view.incoming) {
        auto it = all.find(c);
        if (it == all.end())
            continue;
        it->second.held += n;
        it->second.waiting = std::max(0, it->second.waiting - n);
    }
    for (auto &[c, client] : all)
        client.usage = usage(c, view.running, view.now);
    return all;
}

int FairShare::share(const std::vector<std::uint64_t> &queued, const std::vector<Running> &running,
                     int slots) {
    std::set<std::uint64_t> clients(queued.begin(), queued.end());
    for (const Running &r : running)
        clients.insert(r.client);
    return std::max(1, slots / static_cast<int>(std::max<std::size_t>(1, clients.size())));
}

std::size_t FairShare::next(const View &view) const {
    auto all = clients(view);
    int fair = share(view.queued, view.running, view.slots);
    auto key = [&](std::size_t i) {
        const Client &c = all.at(view.queued[i]);
        return std::make_tuple(c.usage, c.held, i);
    };
    auto least = [&](auto &&admit) {
        std::optional<std::size_t> best;
        for (std::size_t i = 0; i < view.queued.size(); ++i)
            if (admit(all.at(view.queued[i])) && (!best || key(i) < key(*best)))
                best = i;
        return best;
    };
    std::size_t best = *least([](const Client &) { return true; });
    const Client &lightest = all.at(view.queued[best]);
    // Below its share and not much heavier than the least used: its share first.
    auto below =
        least([&](const Client &c) { return c.held < fair && !much_lighter(lightest, c); });
    return lightest.held < fair || !below ? best : *below;
}

bool FairShare::past_quantum(const Running &r) const {
    return r.seconds > quantum_s_ * std::ldexp(1.0, std::min(r.preemptions, 20));
}

bool FairShare::may_yield(const Running &r) const { return r.preemptions == 0 || past_quantum(r); }

std::optional<FairShare::Taken> FairShare::victim(const View &view) const {
    auto all = clients(view);
    int fair = share(view.queued, view.running, view.slots);
    if (auto taken = over_share(view, all, fair))
        return taken;
    if (auto taken = much_heavier(view, all))
        return taken;
    return turn(view, all);
}

// Rule 1: below its share, from a client above it that is not much lighter.
std::optional<FairShare::Taken> FairShare::over_share(const View &view,
                                                      const std::map<std::uint64_t, Client> &all,
                                                      int fair) const {
    std::optional<std::uint64_t> taker;
    for (const auto &[c, client] : all)
        if (client.waiting > 0 && client.held < fair &&
            (!taker || std::tie(client.held, client.usage) <
                           std::tie(all.at(*taker).held, all.at(*taker).usage)))
            taker = c;
    if (!taker)
        return std::nullopt;
    const Running *chosen = nullptr;
    for (const Running &r : view.running) {
        const Client &v = all.at(r.client);
        if (v.held <= fair || much_lighter(v, all.at(*taker)))
            continue;
        if (!chosen) {
            chosen = &r;
            continue;
        }
        const Client &w = all.at(chosen->client);
        if (std::tie(v.held, v.usage, r.seconds) > std::tie(w.held, w.usage, chosen->seconds))
            chosen = &r; // holding most, then most used; its longest-running job
    }
    if (!chosen)
        return std::nullopt;
    return Taken{chosen->job, *taker};
}

// Rule 2: the least used waiting client, from a client much heavier than it.
std::optional<FairShare::Taken>
FairShare::much_heavier(const View &view, const std::map<std::uint64_t, Client> &all) const {
    std::optional<std::uint64_t> taker;
    for (const auto &[c, client] : all)
        if (client.waiting > 0 && (!taker || client.usage < all.at(*taker).usage))
            taker = c;
    if (!taker)
        return std::nullopt;
    const Running *chosen = nullptr;
    for (const Running &r : view.running) {
        const Client &v = all.at(r.client);
        if (!much_lighter(all.at(*taker), v) || !may_yield(r))
            continue;
        if (!chosen ||
            std::tie(v.usage, r.seconds) > std::tie(all.at(chosen->client).usage, chosen->seconds))
            chosen = &r;
    }
    if (!chosen)
        return std::nullopt;
    return Taken{chosen->job, *taker};
}

// Rule 3: every client at its share; one holding none takes a turn from a job past its
// quantum, the youngest such (the least is lost) of the client holding the most.
std::optional<FairShare::Taken> FairShare::turn(const View &view,
                                                const std::map<std::uint64_t, Client> &all) const {
    std::optional<std::uint64_t> taker;
    for (const auto &[c, client] : all)
        if (client.waiting > 0 && client.held == 0 &&
            (!taker || client.usage < all.at(*taker).usage))
            taker = c;
    if (!taker)
        return std::nullopt;
    const Running *chosen = nullptr;
    for (const Running &r : view.running) {
        const Client &v = all.at(r.client);
        if (!past_quantum(r) || much_lighter(v, all.at(*taker)))
            continue;
        if (!chosen) {
            chosen = &r;
            continue;
        }
        const Client &w = all.at(chosen->client);
        if (std::tie(v.held, v.usage) > std::tie(w.held, w.usage) ||
            (std::tie(v.held, v.usage) == std::tie(w.held, w.usage) && r.seconds < chosen->seconds))
            chosen = &r;
    }
    if (!chosen)
        return std::nullopt;
    return Taken{chosen->job, *taker};
}

} // namespace envdesign::cluster
