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
/// first, "<first>_over_<c>" (the ratio of their summed times).
inline void runPaired(benchmark::State& state, Clock clock, const std::vector<Contender>& contenders)
{
    const std::size_t count = contenders.size();
    std::vector<double> totals(count, 0.0);
    std::size_t turn = 0;
    for (auto _ : state) {
        for (std::size_t k = 0; k < count; ++k) {
            const Contender& contender = contenders[(turn + k) % count];
            if (contender.before)
                contender.before();
            const double start = now(clock);
            contender.work();
            totals[(turn + k) % count] += now(clock) - start;
            if (contender.after)
                contender.after();
        }
        ++turn;
    }
    const double iterations = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
    for (std::size_t k = 0; k < count; ++k)
        state.counters[contenders[k].name + "_ms"] = 1e3 * totals[k] / iterations;
    for (std::size_t k = 1; k < count; ++k)
        state.counters[contenders[0].name + "_over_" + contenders[k].name] = totals[0] / totals[k];
}

} // namespace q3bench
