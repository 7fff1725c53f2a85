// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The compile-time link between core/Limits.h and the public constants that
// document each limit: changing one without the other fails the build.

#include "core/Limits.h"

#include "QD3DController.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DStyle.h"
#include "Q3PixmapPNG.h"

namespace q3::limits {

static_assert(kMaxArrayCount == kQ3GeometryMaxArrayCount, "QD3DGeometry.h documents kMaxArrayCount");
static_assert(kMaxCurveOrder == kQ3NURBCurveMaxOrder, "QD3DGeometry.h documents kMaxCurveOrder");
static_assert(kMaxChannelBytes == kQ3ControllerSetChannelMaxDataSize,
              "QD3DController.h documents kMaxChannelBytes");
static_assert(kMaxPatchOrder == kQ3NURBPatchMaxOrder, "QD3DGeometry.h documents kMaxPatchOrder");
static_assert(kMaxTrianglesPerPatch == kQ3SubdivisionMaxTrianglesPerPatch,
              "QD3DStyle.h documents kMaxTrianglesPerPatch");
static_assert(kMaxSegmentsPerCurve == kQ3SubdivisionMaxSegmentsPerCurve,
              "QD3DStyle.h documents kMaxSegmentsPerCurve");
static_assert(kMaxTrianglesPerSurface == kQ3SubdivisionMaxTrianglesPerSurface,
              "QD3DStyle.h documents kMaxTrianglesPerSurface");
static_assert(kMaxConstantSegments == kQ3SubdivisionMaxConstantSegments,
              "QD3DStyle.h documents kMaxConstantSegments");
static_assert(kViewSegmentsPerPixel == kQ3SubdivisionViewSegmentsPerPixel,
              "QD3DStyle.h documents kViewSegmentsPerPixel");
static_assert(kMinScreenSpaceC1 == kQ3SubdivisionMinScreenSpaceC1, "QD3DStyle.h documents kMinScreenSpaceC1");
static_assert(kMaxGroupNesting == kQ3GroupMaxNesting, "QD3DGroup.h documents kMaxGroupNesting");
static_assert(kMaxPngPixels == kQ3PixmapPNGMaxPixels, "Q3PixmapPNG.h documents kMaxPngPixels");
static_assert(kSubdivisionDefault == kQ3SubdivisionDefaultC1, "QD3DStyle.h documents kSubdivisionDefault");

} // namespace q3::limits
