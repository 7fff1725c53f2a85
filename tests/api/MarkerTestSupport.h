// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What the Marker and PixmapMarker API tests share: QD3DGeometry.h gives both
// the same six position and offset calls, so one check reads, refuses and
// writes them for either type.

#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"

#include <vector>

namespace q3test {

/// One marker type's position and offset calls.
struct MarkerPlacementCalls {
    TQ3Status (*getPosition)(TQ3GeometryObject, TQ3Point3D*);
    TQ3Status (*setPosition)(TQ3GeometryObject, const TQ3Point3D*);
    TQ3Status (*getXOffset)(TQ3GeometryObject, long*);
    TQ3Status (*setXOffset)(TQ3GeometryObject, long);
    TQ3Status (*getYOffset)(TQ3GeometryObject, long*);
    TQ3Status (*setYOffset)(TQ3GeometryObject, long);
};

inline const MarkerPlacementCalls kMarkerPlacement{Q3Marker_GetPosition, Q3Marker_SetPosition,
                                                   Q3Marker_GetXOffset,  Q3Marker_SetXOffset,
                                                   Q3Marker_GetYOffset,  Q3Marker_SetYOffset};
inline const MarkerPlacementCalls kPixmapMarkerPlacement{
    Q3PixmapMarker_GetPosition, Q3PixmapMarker_SetPosition, Q3PixmapMarker_GetXOffset,
    Q3PixmapMarker_SetXOffset,  Q3PixmapMarker_GetYOffset,  Q3PixmapMarker_SetYOffset};

class MarkerApiTestBase : public OwningApiTest {
protected:
    /// Reads the placement `marker` was made with; checks that every bad
    /// call (non-finite coordinates, NULL results, NULL, stray, dead and
    /// `wrong` handles) fails with its code and changes nothing; then writes
    /// the position (-1, -2, -3) and offsets (xMoved, 77) and reads them back.
    void expectPlacementCalls(const MarkerPlacementCalls& calls, TQ3GeometryObject marker,
                              const TQ3Point3D& position, long xOffset, long yOffset,
                              const std::vector<TQ3Object>& wrong, long xMoved)
    {
        const unsigned long edit = Q3Shared_GetEditIndex(marker);
        TQ3Point3D p{};
        long offset = 0;
        ASSERT_EQ(calls.getPosition(marker, &p), kQ3Success);
        EXPECT_TRUE(samePoint(p, position));
        ASSERT_EQ(calls.getXOffset(marker, &offset), kQ3Success);
        EXPECT_EQ(offset, xOffset);
        ASSERT_EQ(calls.getYOffset(marker, &offset), kQ3Success);
        EXPECT_EQ(offset, yOffset);

        for (float bad : kNonFinite)
            for (const TQ3Point3D& q : {TQ3Point3D{bad, 0, 0}, TQ3Point3D{0, bad, 0}, TQ3Point3D{0, 0, bad}})
                EXPECT_Q3_ERROR(calls.setPosition(marker, &q), kQ3ErrorInvalidData);
        EXPECT_Q3_ERROR(calls.setPosition(marker, nullptr), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(calls.getPosition(marker, nullptr), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(calls.getXOffset(marker, nullptr), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(calls.getYOffset(marker, nullptr), kQ3ErrorNULLParameter);
        for (TQ3Object other : wrong) {
            EXPECT_Q3_ERROR(calls.getPosition(other, &p), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(calls.setPosition(other, &p), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(calls.getXOffset(other, &offset), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(calls.setXOffset(other, 1), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(calls.getYOffset(other, &offset), kQ3ErrorInvalidObjectType);
            EXPECT_Q3_ERROR(calls.setYOffset(other, 1), kQ3ErrorInvalidObjectType);
        }
        EXPECT_Q3_ERROR(calls.setXOffset(nullptr, 1), kQ3ErrorNULLParameter);
        EXPECT_Q3_ERROR(calls.setYOffset(strayHandle(), 1), kQ3ErrorInvalidObject);
        EXPECT_Q3_ERROR(calls.getXOffset(deadObject(), &offset), kQ3ErrorInvalidObject);
        EXPECT_EQ(Q3Shared_GetEditIndex(marker), edit);
        ASSERT_EQ(calls.getPosition(marker, &p), kQ3Success);
        EXPECT_TRUE(samePoint(p, position));

        const TQ3Point3D moved{-1, -2, -3};
        ASSERT_EQ(calls.setPosition(marker, &moved), kQ3Success);
        ASSERT_EQ(calls.setXOffset(marker, xMoved), kQ3Success);
        ASSERT_EQ(calls.setYOffset(marker, 77), kQ3Success);
        EXPECT_GT(Q3Shared_GetEditIndex(marker), edit);
        ASSERT_EQ(calls.getPosition(marker, &p), kQ3Success);
        EXPECT_TRUE(samePoint(p, moved));
        ASSERT_EQ(calls.getXOffset(marker, &offset), kQ3Success);
        EXPECT_EQ(offset, xMoved);
        ASSERT_EQ(calls.getYOffset(marker, &offset), kQ3Success);
        EXPECT_EQ(offset, 77);
    }
};

} // namespace q3test
