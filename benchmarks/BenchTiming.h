// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Paired timing: Q3 and its peer take turns inside one benchmark loop, each
// timed on its own, and the order rotates every iteration. On a shared, noisy
// machine the load changes over seconds; contenders that alternate every few
// milliseconds see the same load, so their ratio stays put while the
// absolute times drift. Each repetition reports its ratio of summed times;
// run.sh takes the median over repetitions.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace q3bench {

/// Every benchmark is timed on the wall clock: what a user waits for,
/// including the work llvmpipe's threads and the kernel do on the caller's
/// behalf (page cache copies, allocation), which a thread's CPU time hides.
enum class Clock {
    kWall, ///< steady wall clock
};

inline double now(Clock)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// One contender: the name its counters carry, the work of one turn, and
/// optional untimed steps around each turn.
struct Contender {
    std::string name;
    std::function<void()> work;
    std::function<void()> before = {};
    std::function<void()> after = {};
};

/// Runs the benchmark loop with every contender taking one turn per
/// iteration, the order rotating, and records per contender c the counter
/// "<c>_ms" (mean milliseconds per turn) and, for every contender after the
/// first, "<first>_over_<c>" (the ratio of their summed times) and
/// "<first>_over_<c>_median" (the median over iterations of the ratio of
/// their turns in that iteration: a turn that the machine's other work
/// lengthens moves it less than the sums).
inline void runPaired(benchmark::State& state, Clock clock, const std::vector<Contender>& contenders)
{
    const std::size_t count = contenders.size();
    std::vector<double> totals(count, 0.0);
    std::vector<double> turns(count, 0.0);
    std::vector<std::vector<double>> ratios(count);
    std::size_t turn = 0;
    for (auto _ : state) {
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t which = (turn + k) % count;
            const Contender& contender = contenders[which];
            if (contender.before)
                contender.before();
            const double start = now(clock);
            contender.work();
            turns[which] = now(clock) - start;
            totals[which] += turns[which];
            if (contender.after)
                contender.after();
        }
        for (std::size_t k = 1; k < count; ++k)
            ratios[k].push_back(turns[0] / turns[k]);
        ++turn;
    }
    const double iterations = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
    for (std::size_t k = 0; k < count; ++k)
        state.counters[contenders[k].name + "_ms"] = 1e3 * totals[k] / iterations;
    for (std::size_t k = 1; k < count; ++k) {
        const std::string name = contenders[0].name + "_over_" + contenders[k].name;
        state.counters[name] = totals[0] / totals[k];
        std::vector<double>& r = ratios[k];
        if (!r.empty()) {
            std::nth_element(r.begin(), r.begin() + std::ptrdiff_t(r.size() / 2), r.end());
            state.counters[name + "_median"] = r[r.size() / 2];
        }
    }
}

} // namespace q3bench
