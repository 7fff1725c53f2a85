// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Every limit Q3 imposes on what a caller may ask for, in one place. Each one
// that a public header documents is checked at compile time against that
// header's constant (core/Limits.cpp), so the two cannot drift apart. This
// header includes nothing of Q3's, so the pure math in geometry/nurbs may use
// it too.

#include <cstddef>
#include <cstdint>

namespace q3::limits {

/// The most entries of any one array in a geometry's data (vertices, control
/// points, knots, triangles, attribute values...): kQ3GeometryMaxArrayCount.
/// Far above any real model, and it keeps every size computation (count times
/// element size, count plus order) far from overflow.
constexpr std::size_t kMaxArrayCount = std::size_t{1} << 28;

/// Curve order (degree + 1) bounds: 2 and kQ3NURBCurveMaxOrder.
constexpr unsigned kMinCurveOrder = 2;
constexpr unsigned kMaxCurveOrder = 16;

/// NURB patch order bounds, in u and in v: 2 and kQ3NURBPatchMaxOrder.
constexpr unsigned kMinPatchOrder = 2;
constexpr unsigned kMaxPatchOrder = 11;

/// The most triangles one NURB patch is drawn with (every pair of knot spans
/// still gets two): kQ3SubdivisionMaxTrianglesPerPatch.
constexpr std::size_t kMaxTrianglesPerPatch = std::size_t{1} << 20;

/// The most line segments one NURB curve is drawn with:
/// kQ3SubdivisionMaxSegmentsPerCurve.
constexpr std::size_t kMaxSegmentsPerCurve = std::size_t{1} << 20;

/// The most segments a world- or screen-space curve is drawn with in a view,
/// per pixel of the pane's width plus height:
/// kQ3SubdivisionViewSegmentsPerPixel.
constexpr std::size_t kViewSegmentsPerPixel = 16;

/// The smallest screen-space c1 or c2, in pixels: kQ3SubdivisionMinScreenSpaceC1.
constexpr float kMinScreenSpaceC1 = 0.125f;

/// The most triangles one quadric or solid (box, cone, cylinder, disk,
/// ellipsoid, torus) is drawn with: kQ3SubdivisionMaxTrianglesPerSurface.
constexpr std::size_t kMaxTrianglesPerSurface = std::size_t{1} << 20;

/// The largest constant-method c1 or c2, in segments per knot span:
/// kQ3SubdivisionMaxConstantSegments.
constexpr std::uint32_t kMaxConstantSegments = 1024;

/// How deep display groups may nest inside each other when drawn, bounded or
/// duplicated: kQ3GroupMaxNesting.
constexpr std::size_t kMaxGroupNesting = 256;

/// The most pixels of a PNG file Q3Pixmap_ReadPNG reads: 16384 x 16384, the
/// largest image Q3 renders (kQ3PixmapPNGMaxPixels).
constexpr std::uint64_t kMaxPngPixels = std::uint64_t{1} << 28;

/// The most bytes a memory storage grows to, and a metafile Q3 reads or
/// writes (2 GiB - 1): past it a storage refuses to grow and a reader refuses
/// the file, so a corrupt size never allocates without bound.
constexpr std::size_t kMaxStorageBytes = (std::size_t{1} << 31) - 1;

/// How deep containers and groups may nest in a metafile:
/// kMaxGroupNesting, the limit a group drawn from it meets anyway.
constexpr std::size_t kMaxMetafileNesting = kMaxGroupNesting;

/// The widest and tallest texture image, in pixels (QD3DShader.h's data
/// rules): a decoded image is then at most 64 MiB.
constexpr std::uint32_t kMaxTextureSize = 4096;

/// The value substituted for an unreasonable c1 or c2: kQ3SubdivisionDefaultC1.
constexpr float kSubdivisionDefault = 20.0f;

/// The most values and channels a controller may declare (QD3DController.h),
/// so a driver's counts never allocate without bound.
constexpr unsigned long kMaxControllerValues = 1024;
constexpr unsigned long kMaxControllerChannels = 1024;
/// The most bytes of one controller channel: kQ3ControllerSetChannelMaxDataSize.
constexpr unsigned long kMaxChannelBytes = 256;
/// How many event coordinates a tracker's ring buffer keeps.
constexpr std::size_t kTrackerEventCount = 16;

} // namespace q3::limits
