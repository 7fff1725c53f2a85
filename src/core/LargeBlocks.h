// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The memory of the arrays in QuickDraw 3D data structs (a geometry's own
// data, what Q3xxx_GetData hands out and Q3xxx_EmptyData frees). Blocks are
// plain malloc blocks, so a caller that frees one with free() is still right;
// but a large block released here is kept for the next allocation of a
// similar size instead of going back to the system. A program that gets a
// decomposed curve's vertices out on every frame then reuses the same
// mapped pages rather than having the kernel map and zero them again (each
// GetData / EmptyData pair of a 64,000-vertex polyline cost ~700 page faults).

#include <cstddef>

namespace q3::memory {

/// Blocks at least this large are recycled.
constexpr std::size_t kRecycledBlockMinBytes = std::size_t(256) * 1024;
/// At most this many blocks, and this many bytes in all, are kept.
constexpr std::size_t kRecycledBlockCount = 6;
constexpr std::size_t kRecycledBytesMax = std::size_t(64) * 1024 * 1024;

/// malloc(bytes), or a kept block that holds bytes and is at most twice as
/// large; nullptr when memory runs out.
void* allocate(std::size_t bytes);

/// free(block) for small blocks; a large one is kept (the oldest kept block
/// is freed when the cache is full). NULL is ignored.
void release(void* block);

/// Frees every kept block (Q3Exit does).
void releaseKept();

} // namespace q3::memory
