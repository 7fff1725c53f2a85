// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Reading and writing a 1,000,000-triangle TriMesh as a 3DMF file, binary and
// text, through Q3's file objects on a path storage; against plain fwrite and
// fread of the same bytes in the same process. Each benchmark reports bytes
// per second of the file (MB/s) so the two compare directly.
//
// ReadModel: a binary model of about 1 MB as an application ships one (a
// group of TriMeshes with vertex normals and uvs, and quadrics with
// attribute sets) read through the public path from memory
// (Q3MemoryStorage_New, Q3File_OpenRead, Q3File_ReadObject to the end,
// Q3File_Close, every object disposed of), paired with fread of the same
// bytes from a file (BenchTiming.h): q3_MBps, fread_MBps, q3_over_fread.

#include "QD3D.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

#include "BenchModel.h"
#include "BenchTiming.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

constexpr unsigned long kSide = 709; // 708 * 708 * 2 = 1,002,528 triangles

struct Session {
    Session() { Q3Initialize(); }
    ~Session() { Q3Exit(); }
};

TQ3GeometryObject bigMesh()
{
    std::vector<TQ3Point3D> points;
    points.reserve(kSide * kSide);
    for (unsigned long y = 0; y < kSide; ++y)
        for (unsigned long x = 0; x < kSide; ++x)
            points.push_back({float(x), float(y), float((x * 7 + y * 3) % 5)});
    std::vector<TQ3TriMeshTriangleData> triangles;
    for (unsigned long y = 0; y + 1 < kSide; ++y)
        for (unsigned long x = 0; x + 1 < kSide; ++x) {
            const unsigned long a = y * kSide + x;
            triangles.push_back({{a, a + 1, a + kSide}});
            triangles.push_back({{a + 1, a + kSide + 1, a + kSide}});
        }
    TQ3TriMeshData data{};
    data.numTriangles = triangles.size();
    data.triangles = triangles.data();
    data.numPoints = points.size();
    data.points = points.data();
    data.bBox = {{0, 0, 0}, {float(kSide - 1), float(kSide - 1), 4}, kQ3False};
    return Q3TriMesh_New(&data);
}

std::string path(const char* name)
{
    return "/tmp/q3_bench_3dmf_" + std::to_string(::getpid()) + "_" + name;
}

void writeFile(TQ3Object object, const std::string& to, TQ3FileMode mode)
{
    TQ3StorageObject storage = Q3UnixPathStorage_New(to.c_str());
    TQ3FileObject file = Q3File_New();
    TQ3ViewObject view = Q3View_New();
    Q3File_SetStorage(file, storage);
    Q3File_OpenWrite(file, mode);
    Q3View_StartWriting(view, file);
    Q3Object_Submit(object, view);
    Q3View_EndWriting(view);
    Q3File_Close(file);
    Q3Object_Dispose(view);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
}

TQ3Object readFile(const std::string& from)
{
    TQ3StorageObject storage = Q3UnixPathStorage_New(from.c_str());
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    TQ3FileMode mode;
    Q3File_OpenRead(file, &mode);
    TQ3Object object = Q3File_ReadObject(file);
    Q3File_Close(file);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    return object;
}

std::vector<unsigned char> slurp(const std::string& from)
{
    std::vector<unsigned char> bytes;
    if (std::FILE* f = std::fopen(from.c_str(), "rb")) {
        std::fseek(f, 0, SEEK_END);
        bytes.resize(static_cast<std::size_t>(std::ftell(f)));
        std::fseek(f, 0, SEEK_SET);
        bytes.resize(std::fread(bytes.data(), 1, bytes.size(), f));
        std::fclose(f);
    }
    return bytes;
}

void Q3Write(benchmark::State& state, TQ3FileMode mode, const char* name)
{
    Session session;
    TQ3GeometryObject mesh = bigMesh();
    const std::string to = path(name);
    for (auto _ : state)
        writeFile(mesh, to, mode);
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(slurp(to).size()));
    std::remove(to.c_str());
    Q3Object_Dispose(mesh);
}

void Q3Read(benchmark::State& state, TQ3FileMode mode, const char* name)
{
    Session session;
    TQ3GeometryObject mesh = bigMesh();
    const std::string from = path(name);
    writeFile(mesh, from, mode);
    Q3Object_Dispose(mesh);
    for (auto _ : state) {
        TQ3Object object = readFile(from);
        if (object == nullptr)
            state.SkipWithError("the file cannot be read");
        else
            Q3Object_Dispose(object);
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(slurp(from).size()));
    std::remove(from.c_str());
}

// The peers: the same bytes through fwrite and fread.
void PlainWrite(benchmark::State& state, TQ3FileMode mode, const char* name)
{
    std::vector<unsigned char> bytes;
    {
        Session session;
        TQ3GeometryObject mesh = bigMesh();
        writeFile(mesh, path(name), mode);
        Q3Object_Dispose(mesh);
        bytes = slurp(path(name));
    }
    for (auto _ : state) {
        std::FILE* f = std::fopen(path(name).c_str(), "wb");
        std::fwrite(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes.size()));
    std::remove(path(name).c_str());
}

void PlainRead(benchmark::State& state, TQ3FileMode mode, const char* name)
{
    {
        Session session;
        TQ3GeometryObject mesh = bigMesh();
        writeFile(mesh, path(name), mode);
        Q3Object_Dispose(mesh);
    }
    std::size_t size = 0;
    for (auto _ : state) {
        const auto bytes = slurp(path(name));
        size = bytes.size();
        benchmark::DoNotOptimize(bytes.data());
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(size));
    std::remove(path(name).c_str());
}

void ReadModel(benchmark::State& state)
{
    Session session;
    const std::vector<unsigned char> bytes = q3bench::modelBytes();
    const std::size_t objects = 1 + 4 * 4;
    if (q3bench::readModel(bytes) != objects) {
        state.SkipWithError("the model does not read back");
        return;
    }
    const std::string from = path("model.bin");
    if (std::FILE* f = std::fopen(from.c_str(), "wb")) {
        std::fwrite(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
    }
    std::vector<unsigned char> buffer(bytes.size());
    q3bench::runPaired(state, q3bench::Clock::kWall,
                       {{"q3", [&] { benchmark::DoNotOptimize(q3bench::readModel(bytes)); }},
                        {"fread", [&] {
                             std::FILE* f = std::fopen(from.c_str(), "rb");
                             benchmark::DoNotOptimize(std::fread(buffer.data(), 1, buffer.size(), f));
                             std::fclose(f);
                         }}});
    const double megabytes = double(bytes.size()) / 1e6;
    state.counters["bytes"] = double(bytes.size());
    state.counters["q3_MBps"] = megabytes / (state.counters["q3_ms"] / 1e3);
    state.counters["fread_MBps"] = megabytes / (state.counters["fread_ms"] / 1e3);
    std::remove(from.c_str());
}

} // namespace

BENCHMARK_CAPTURE(Q3Write, Binary, kQ3FileModeNormal, "w.bin")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(PlainWrite, Binary, kQ3FileModeNormal, "pw.bin")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3Read, Binary, kQ3FileModeNormal, "r.bin")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(PlainRead, Binary, kQ3FileModeNormal, "pr.bin")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3Write, Text, kQ3FileModeText, "w.txt")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(PlainWrite, Text, kQ3FileModeText, "pw.txt")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Q3Read, Text, kQ3FileModeText, "r.txt")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(PlainRead, Text, kQ3FileModeText, "pr.txt")->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK(ReadModel)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
