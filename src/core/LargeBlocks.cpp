// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "core/LargeBlocks.h"

#include <malloc.h>

#include <array>
#include <cstdlib>
#include <mutex>

namespace q3::memory {
namespace {

struct Kept {
    void* block = nullptr;
    std::size_t capacity = 0;
    unsigned long long age = 0;  // when it was released (a counter)
};

struct Cache {
    std::mutex lock;
    std::array<Kept, kRecycledBlockCount> kept{};
    std::size_t bytes = 0;
    unsigned long long clock = 0;
};

Cache& cache()
{
    // Never destroyed: blocks may be released while static objects of the
    // program are destroyed, after this file's statics would be.
    static Cache* instance = new Cache;
    return *instance;
}

} // namespace

void* allocate(std::size_t bytes)
{
    if (bytes >= kRecycledBlockMinBytes) {
        Cache& c = cache();
        std::lock_guard<std::mutex> guard(c.lock);
        Kept* best = nullptr;
        for (Kept& k : c.kept)
            if (k.block != nullptr && k.capacity >= bytes && k.capacity / 2 <= bytes &&
                (best == nullptr || k.capacity < best->capacity))
                best = &k;
        if (best != nullptr) {
            void* block = best->block;
            c.bytes -= best->capacity;
            *best = Kept{};
            return block;
        }
    }
    return std::malloc(bytes);
}

void release(void* block)
{
    if (block == nullptr)
        return;
    const std::size_t capacity = malloc_usable_size(block);
    if (capacity < kRecycledBlockMinBytes || capacity > kRecycledBytesMax) {
        std::free(block);
        return;
    }
    void* evicted = nullptr;
    {
        Cache& c = cache();
        std::lock_guard<std::mutex> guard(c.lock);
        // An empty slot, else the oldest block makes room.
        Kept* slot = nullptr;
        for (Kept& k : c.kept)
            if (k.block == nullptr) {
                slot = &k;
                break;
            }
        if (slot == nullptr) {
            slot = &c.kept[0];
            for (Kept& k : c.kept)
                if (k.age < slot->age)
                    slot = &k;
            evicted = slot->block;
            c.bytes -= slot->capacity;
            *slot = Kept{};
        }
        // Over the byte budget, older blocks go too.
        while (c.bytes + capacity > kRecycledBytesMax) {
            Kept* oldest = nullptr;
            for (Kept& k : c.kept)
                if (k.block != nullptr && (oldest == nullptr || k.age < oldest->age))
                    oldest = &k;
            if (oldest == nullptr)
                break;
            std::free(oldest->block);
            c.bytes -= oldest->capacity;
            *oldest = Kept{};
        }
        *slot = Kept{block, capacity, ++c.clock};
        c.bytes += capacity;
    }
    std::free(evicted);
}

void releaseKept()
{
    Cache& c = cache();
    std::lock_guard<std::mutex> guard(c.lock);
    for (Kept& k : c.kept) {
        std::free(k.block);
        k = Kept{};
    }
    c.bytes = 0;
}

} // namespace q3::memory
