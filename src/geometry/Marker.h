// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

namespace q3 {

extern const ClassInfo kMarkerClass;

/// A marker: a bitmap drawn in screen space at the image of its location.
/// Invariant: its data obeys the TQ3MarkerData rules of QD3DGeometry.h (a
/// finite location, a non-empty bitmap whose rows hold its width, of at most
/// kQ3GeometryMaxArrayCount bytes, a bit order of the enumeration).
class Marker final : public DataGeometry<Marker, TQ3MarkerData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypeMarker;
    static constexpr const char* kName = "marker";
    static constexpr const char* kDataName = "markerData";
    static constexpr TQ3AttributeSet TQ3MarkerData::*kOwnSet = &TQ3MarkerData::markerAttributeSet;

    /// The TQ3MarkerData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3MarkerData& data);
    /// The bitmap rules alone (Q3Marker_SetBitmap), in the same order.
    static void checkBitmap(const TQ3Bitmap& bitmap);
    /// checkBitmap's rules beyond the bitmap's description (its image
    /// present, rowBytes * height within the limit), for data that passed it.
    static void checkBitmapRules(const TQ3Bitmap& bitmap);

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kMarkerClass; }
    /// One vertex at the location and the bitmap anchored at it.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    bool isPrimitive() const override { return true; }

    void setPosition(const TQ3Point3D& location);
    void setXOffset(long xOffset);
    void setYOffset(long yOffset);
    /// A malloc'ed copy of the bitmap's bits in `out` (the other fields as
    /// they are), for Q3Bitmap_Empty to free.
    void copyBitmap(TQ3Bitmap& out) const;
    /// Checks bitmap, copies its bits, then frees the old ones.
    void setBitmap(const TQ3Bitmap& bitmap);
};

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3Bitmap> {
    static auto fields()
    {
        using B = TQ3Bitmap;
        return std::make_tuple(requiredArray("image", &B::image, countProduct(&B::rowBytes, &B::height)),
                               value("width", &B::width), value("height", &B::height),
                               value("rowBytes", &B::rowBytes), value("bitOrder", &B::bitOrder));
    }
};

template <>
struct Describe<TQ3MarkerData> {
    static auto fields()
    {
        using D = TQ3MarkerData;
        return std::make_tuple(finite("location", &D::location), value("xOffset", &D::xOffset),
                               value("yOffset", &D::yOffset), nested("bitmap", &D::bitmap),
                               handle<AttributeSet>("markerAttributeSet", &D::markerAttributeSet));
    }
};
} // namespace layout

} // namespace q3
