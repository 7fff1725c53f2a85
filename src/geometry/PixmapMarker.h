// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DGeometry.h"
#include "core/DataLayout.h"
#include "geometry/DataGeometry.h"

namespace q3 {

class Storage;

extern const ClassInfo kPixmapMarkerClass;

/// A pixmap marker: a colour image, kept in a storage object, drawn in
/// screen space at the image of its position. Invariant: its data obeys the
/// TQ3PixmapMarkerData rules of QD3DGeometry.h (a finite position; a pixmap
/// of a known pixel type and size, byte and bit orders of the enumeration,
/// rows that hold its width, at most kQ3GeometryMaxArrayCount bytes, in a
/// live storage that held them all when it was set). The storage's contents
/// may change later; drawing reads them and refuses a storage grown too
/// small.
class PixmapMarker final : public DataGeometry<PixmapMarker, TQ3PixmapMarkerData> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3GeometryTypePixmapMarker;
    static constexpr const char* kName = "pixmap marker";
    static constexpr const char* kDataName = "pixmapMarkerData";
    static constexpr TQ3AttributeSet TQ3PixmapMarkerData::*kOwnSet =
        &TQ3PixmapMarkerData::pixmapMarkerAttributeSet;

    /// The TQ3PixmapMarkerData rules of QD3DGeometry.h, in their order.
    static void check(const TQ3PixmapMarkerData& data);
    /// The pixmap rules alone (Q3PixmapMarker_SetPixmap), in the same order.
    static void checkPixmap(const TQ3StoragePixmap& pixmap);
    /// checkPixmap's rules beyond the pixmap's description (its image
    /// present), for data that passed it.
    static void checkPixmapRules(const TQ3StoragePixmap& pixmap);

    using DataGeometry::DataGeometry;

    const ClassInfo& classInfo() const override { return kPixmapMarkerClass; }
    /// One vertex at the position and the pixmap, read from its storage now,
    /// anchored at it. Throws kQ3ErrorInvalidData when the storage no longer
    /// holds the pixmap.
    void decompose(const DecomposeContext& context, PrimitiveSink& sink) const override;
    /// The position alone, without reading the storage.
    void bound(const DecomposeContext& context, std::vector<glm::dvec3>& points) const override;
    bool isPrimitive() const override { return true; }

    void setPosition(const TQ3Point3D& position);
    void setXOffset(long xOffset);
    void setYOffset(long yOffset);
    /// The pixmap with a new reference to its storage in `out`.
    void copyPixmap(TQ3StoragePixmap& out) const;
    /// Checks pixmap, references its storage, then releases the old one.
    void setPixmap(const TQ3StoragePixmap& pixmap);
};

// The data description (core/DataLayout.h).
namespace layout {
template <>
struct Describe<TQ3StoragePixmap> {
    static auto fields()
    {
        using P = TQ3StoragePixmap;
        return std::make_tuple(requiredHandle<Storage>("image", &P::image), value("width", &P::width),
                               value("height", &P::height), value("rowBytes", &P::rowBytes),
                               value("pixelSize", &P::pixelSize), value("pixelType", &P::pixelType),
                               value("bitOrder", &P::bitOrder), value("byteOrder", &P::byteOrder));
    }
};

template <>
struct Describe<TQ3PixmapMarkerData> {
    static auto fields()
    {
        using D = TQ3PixmapMarkerData;
        return std::make_tuple(finite("position", &D::position), value("xOffset", &D::xOffset),
                               value("yOffset", &D::yOffset), nested("pixmap", &D::pixmap),
                               handle<AttributeSet>("pixmapMarkerAttributeSet", &D::pixmapMarkerAttributeSet));
    }
};
} // namespace layout

} // namespace q3
