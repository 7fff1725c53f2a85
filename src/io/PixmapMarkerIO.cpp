// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The pixmap marker, 'mrkp' / PixmapMarker (QuickDraw 3D 1.5, after the 1.0
// reference; the layout Quesa reads and writes):
//   position (Point3D), xOffset, yOffset (Int32),
//   width, height, rowBytes, pixelSize (Uns32),
//   pixelType (RGB32 ARGB32 RGB16 ARGB16 RGB16_565 RGB24),
//   bitOrder, byteOrder (BigEndian LittleEndian),
//   rowBytes * height bytes of image: raw data, padded with zeros to a
//   multiple of 4 in binary, one 0x... token in text;
// then, in its container, the marker's attribute set. The image read goes
// into a new memory storage; the marker is built through its class's checks,
// so a file cannot make a marker the API would refuse.

#include "io/ClassIO.h"
#include "io/GeometryIOSupport.h"
#include "io/PixmapIO.h"

#include "geometry/PixmapMarker.h"
#include "base/Storage.h"

#include <cstdint>
#include <string>
#include <vector>

namespace q3::io {
namespace {

Ref<SharedObject> readPixmapMarker(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3PixmapMarkerData data{};
    data.position = in.point3D();
    data.xOffset = in.i32();
    data.yOffset = in.i32();
    TQ3StoragePixmap& pixmap = data.pixmap;
    const std::string image = readPixmapFields(in, pixmap);
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a PixmapMarker has more data than its image");
    Ref<MemoryStorage> storage = storageOf(image);
    pixmap.image = storage.get();
    Ref<AttributeSet> own = context.attributeSet(parts);
    data.pixmapMarkerAttributeSet = own.get();
    return make<PixmapMarker>(data);
}

void writePixmapMarker(WriteContext& context, const Object& object)
{
    const TQ3PixmapMarkerData& data = dataOf<PixmapMarker>(object);
    const TQ3StoragePixmap& pixmap = data.pixmap;
    const std::size_t size = std::size_t{pixmap.height} * pixmap.rowBytes;
    std::vector<unsigned char> image(size);
    const auto& storage = static_cast<const Storage&>(*static_cast<const Object*>(pixmap.image));
    if (storage.read(0, size, image.data()) < size)
        fail(kQ3ErrorInvalidData, "the pixmap marker's storage now holds fewer than the " + std::to_string(size) +
                                      " bytes of rowBytes * height");
    requireInt32Offsets(data.xOffset, data.yOffset, "pixmap marker");
    const AttributeSet* own = setOf(data.pixmapMarkerAttributeSet);
    maybeContainer(context, WriteContext::hasAttributes(own), [&] {
        Encoder& out = context.out();
        out.begin(kQ3GeometryTypePixmapMarker, "PixmapMarker");
        out.point3D(data.position);
        out.i32(static_cast<std::int32_t>(data.xOffset));
        out.i32(static_cast<std::int32_t>(data.yOffset));
        writePixmapFields(out, pixmap, image);
        out.end();
        context.attributeSet(own);
    });
}

} // namespace

void addPixmapMarkerClasses(std::vector<ClassIO>& table)
{
    table.push_back({kQ3GeometryTypePixmapMarker, "PixmapMarker", readPixmapMarker, writePixmapMarker});
}

} // namespace q3::io
