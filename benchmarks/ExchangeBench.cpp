// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Export of the 1 MB binary 3DMF model (BenchModel.h) to glTF 2.0 against
// Q3's own read of it, paired (BenchTiming.h): ExportGlb writes the objects
// read from the model, in one plain group as q3convert does, as a .glb with
// the default subdivision (Q3Exchange_Write); the peer reads the model's
// bytes from memory storage (Q3File_ReadObject to the end). export_over_read
// is the ratio issue 29 bounds by 10. ImportGlb reads that .glb back
// (Q3Exchange_Read), paired with the same 3DMF read.

#include "Q3Exchange.h"

#include "BenchModel.h"
#include "BenchTiming.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <unistd.h>

namespace {

struct Session {
    Session() { Q3Initialize(); }
    ~Session() { Q3Exit(); }
};

std::string path(const char* name)
{
    return "/tmp/q3_bench_exchange_" + std::to_string(::getpid()) + "_" + name;
}

TQ3GroupObject modelGroup(const std::vector<unsigned char>& bytes)
{
    TQ3GroupObject group = Q3Group_New();
    for (TQ3Object object : q3bench::modelObjects(bytes)) {
        Q3Group_AddObject(group, object);
        Q3Object_Dispose(object);
    }
    return group;
}

void ExportGlb(benchmark::State& state)
{
    Session session;
    const std::vector<unsigned char> bytes = q3bench::modelBytes();
    TQ3GroupObject group = modelGroup(bytes);
    const std::string to = path("model.glb");
    if (Q3Exchange_Write(group, to.c_str(), nullptr) != kQ3Success) {
        state.SkipWithError("the model cannot be exported");
        Q3Object_Dispose(group);
        return;
    }
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {{"export", [&] { benchmark::DoNotOptimize(Q3Exchange_Write(group, to.c_str(), nullptr)); }},
                        {"read", [&] { benchmark::DoNotOptimize(q3bench::readModel(bytes)); }}});
    state.counters["bytes_3dmf"] = double(bytes.size());
    if (std::FILE* f = std::fopen(to.c_str(), "rb")) {
        std::fseek(f, 0, SEEK_END);
        state.counters["bytes_glb"] = double(std::ftell(f));
        std::fclose(f);
    }
    std::remove(to.c_str());
    Q3Object_Dispose(group);
}

void ImportGlb(benchmark::State& state)
{
    Session session;
    const std::vector<unsigned char> bytes = q3bench::modelBytes();
    TQ3GroupObject group = modelGroup(bytes);
    const std::string from = path("import.glb");
    const TQ3Status written = Q3Exchange_Write(group, from.c_str(), nullptr);
    Q3Object_Dispose(group);
    if (written != kQ3Success) {
        state.SkipWithError("the model cannot be exported");
        return;
    }
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {{"import", [&] {
                             TQ3GroupObject back = Q3Exchange_Read(from.c_str(), kQ3ExchangeFormatAny);
                             benchmark::DoNotOptimize(back);
                             Q3Object_Dispose(back);
                         }},
                        {"read", [&] { benchmark::DoNotOptimize(q3bench::readModel(bytes)); }}});
    std::remove(from.c_str());
}

} // namespace

BENCHMARK(ExportGlb)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(ImportGlb)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
