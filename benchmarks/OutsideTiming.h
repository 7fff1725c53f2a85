// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the two programs of the outside comparison (PublicPathOutside.cpp,
// GluCountOutside.cpp) share: the call count, the clocks and the one line
// each prints. Each program is its own process and times its whole loop of
// calls once: wall time (steady clock), the process's CPU time (user and
// system, getrusage) and its minor page faults, so that a run on a shared
// machine can be judged by CPU time when the wall clock is disturbed.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <sys/resource.h>
#include <vector>

namespace q3bench {

/// Calls timed per process, as issue 30 measured.
constexpr int kOutsideCalls = 200;

class ProcessClock {
public:
    ProcessClock() : m_wall(std::chrono::steady_clock::now()) { getrusage(RUSAGE_SELF, &m_usage); }

    struct Elapsed {
        double wall = 0;   ///< seconds
        double user = 0;   ///< seconds of user CPU time
        double system = 0; ///< seconds of system CPU time
        long minorFaults = 0;
    };

    Elapsed elapsed() const
    {
        const auto wall = std::chrono::steady_clock::now();
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        Elapsed e;
        e.wall = std::chrono::duration<double>(wall - m_wall).count();
        e.user = seconds(usage.ru_utime) - seconds(m_usage.ru_utime);
        e.system = seconds(usage.ru_stime) - seconds(m_usage.ru_stime);
        e.minorFaults = usage.ru_minflt - m_usage.ru_minflt;
        return e;
    }

private:
    static double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }

    std::chrono::steady_clock::time_point m_wall;
    rusage m_usage{};
};

/// Wall time of each call, to report the median call: on a loaded machine
/// the loop's wall time also holds the time the process waited for a CPU,
/// which lands on a few calls, so the median call shows the work alone.
class CallTimes {
public:
    CallTimes() { m_seconds.reserve(kOutsideCalls); }
    void start() { m_start = std::chrono::steady_clock::now(); }
    void stop() { m_seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count()); }
    double median() const
    {
        std::vector<double> sorted = m_seconds;
        std::sort(sorted.begin(), sorted.end());
        const std::size_t n = sorted.size();
        return n == 0 ? 0.0 : (n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]));
    }

private:
    std::vector<double> m_seconds;
    std::chrono::steady_clock::time_point m_start;
};

/// The one result line: "<tool> calls=... vertices_per_call=... wall_s=...
/// cpu_s=... user_s=... sys_s=... minflt=... median_call_s=... vertices_per_s=...
/// cpu_vertices_per_s=... median_call_vertices_per_s=...", read by outside.py.
inline void printOutsideResult(const char* tool, int calls, std::uint64_t verticesPerCall,
                               const ProcessClock::Elapsed& e, const CallTimes& times)
{
    const double vertices = double(calls) * double(verticesPerCall);
    const double cpu = e.user + e.system;
    const double median = times.median();
    std::printf("%s calls=%d vertices_per_call=%llu wall_s=%.6f cpu_s=%.6f user_s=%.6f sys_s=%.6f minflt=%ld "
                "median_call_s=%.6e vertices_per_s=%.6e cpu_vertices_per_s=%.6e median_call_vertices_per_s=%.6e\n",
                tool, calls, static_cast<unsigned long long>(verticesPerCall), e.wall, cpu, e.user, e.system,
                e.minorFaults, median, vertices / e.wall, cpu > 0 ? vertices / cpu : 0.0,
                median > 0 ? double(verticesPerCall) / median : 0.0);
}

} // namespace q3bench
