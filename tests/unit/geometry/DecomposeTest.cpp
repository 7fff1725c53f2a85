// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// SubdivisionMeasure (geometry/Decompose.h): the cache key holds what a
// tessellation depends on, and one function words the subdivision warning
// for every shape.

#include "geometry/Decompose.h"

#include <gtest/gtest.h>

namespace q3 {
namespace {

SubdivisionMeasure screenSpace(double c1)
{
    SubdivisionMeasure measure;
    measure.method = kQ3SubdivisionMethodScreenSpace;
    measure.options.method = nurbs::Method::kAdaptive;
    measure.options.c1 = c1;
    measure.options.mapping.scale[0] = 320;
    measure.options.mapping.offset[0] = 320;
    measure.options.mapping.requirePositiveW = true;
    return measure;
}

TEST(SubdivisionMeasure, TheKeyChangesWithEveryValueALengthDependsOn)
{
    const std::vector<double> key = screenSpace(4).key();
    EXPECT_EQ(screenSpace(4).key(), key);
    EXPECT_NE(screenSpace(5).key(), key);
    SubdivisionMeasure scaled = screenSpace(4);
    scaled.options.mapping.scale[0] = 321;
    EXPECT_NE(scaled.key(), key);
    SubdivisionMeasure moved = screenSpace(4);
    moved.options.mapping.matrix[0][3] = 1;
    EXPECT_NE(moved.key(), key);
    SubdivisionMeasure capped = screenSpace(4);
    capped.options.maxSegments = 100;
    EXPECT_NE(capped.key(), key);
    SubdivisionMeasure clipped = screenSpace(4);
    clipped.options.hasClip = clipped.options.coarseOutsideClip = true;
    clipped.options.clip[0] = 2;
    EXPECT_NE(clipped.key(), key);
    // Moving the pane moves every image by the same offset: no length changes.
    SubdivisionMeasure panned = screenSpace(4);
    panned.options.mapping.offset[0] = 500;
    EXPECT_EQ(panned.key(), key);
}

TEST(SubdivisionMeasure, TheWarningNamesTheMethodTheShapeTheValuesTheCapAndWhatIsUsed)
{
    SubdivisionShortfall shortfall;
    shortfall.shape = "a NURB curve";
    shortfall.limit = "kQ3SubdivisionMaxSegmentsPerCurve (1048576) segments";
    shortfall.used = "segments up to 0.5 long are used";
    EXPECT_EQ(subdivisionWarning(screenSpace(0.25), shortfall),
              "screen-space subdivision of a NURB curve with c1 = 0.25 would need more than "
              "kQ3SubdivisionMaxSegmentsPerCurve (1048576) segments; segments up to 0.5 long are used");
    SubdivisionMeasure constant;
    constant.options.c1 = 1000;
    constant.options.c2 = 3;
    shortfall.shape = "a NURB patch";
    shortfall.withC2 = true;
    shortfall.limit = "kQ3SubdivisionMaxTrianglesPerPatch (1048576) triangles";
    shortfall.used = "500 x 3 segments per pair of spans are used";
    EXPECT_EQ(subdivisionWarning(constant, shortfall),
              "constant subdivision of a NURB patch with c1 = 1000 and c2 = 3 would need more than "
              "kQ3SubdivisionMaxTrianglesPerPatch (1048576) triangles; 500 x 3 segments per pair of spans are used");
}

} // namespace
} // namespace q3
