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

#include "geometry/PixmapMarker.h"
#include "base/Storage.h"

#include <cstdint>
#include <string>
#include <vector>

namespace q3::io {
namespace {

const std::vector<std::pair<const char*, std::uint32_t>> kPixelTypes = {
    {"RGB32", kQ3PixelTypeRGB32},   {"ARGB32", kQ3PixelTypeARGB32},       {"RGB16", kQ3PixelTypeRGB16},
    {"ARGB16", kQ3PixelTypeARGB16}, {"RGB16_565", kQ3PixelTypeRGB16_565}, {"RGB24", kQ3PixelTypeRGB24}};
const std::vector<std::pair<const char*, std::uint32_t>> kEndians = {{"BigEndian", kQ3EndianBig},
                                                                     {"LittleEndian", kQ3EndianLittle}};

Ref<SharedObject> readPixmapMarker(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3PixmapMarkerData data{};
    data.position = in.point3D();
    data.xOffset = in.i32();
    data.yOffset = in.i32();
    TQ3StoragePixmap& pixmap = data.pixmap;
    pixmap.width = in.u32();
    pixmap.height = in.u32();
    pixmap.rowBytes = in.u32();
    pixmap.pixelSize = in.u32();
    pixmap.pixelType = static_cast<TQ3PixelType>(in.choice(kPixelTypes));
    pixmap.bitOrder = static_cast<TQ3Endian>(in.choice(kEndians));
    pixmap.byteOrder = static_cast<TQ3Endian>(in.choice(kEndians));
    const std::uint64_t size = std::uint64_t{pixmap.height} * pixmap.rowBytes;
    // Refuses an image larger than the API allows or than the binary data
    // holds before anything is allocated; in text, rawData checks the token.
    in.requireRoom(size, 1, 0, "image bytes");
    const std::string image = in.rawData(static_cast<std::size_t>(size));
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a PixmapMarker has more data than its image");
    Ref<MemoryStorage> storage =
        makeShared<MemoryStorage>(reinterpret_cast<const unsigned char*>(image.data()), image.size());
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
        out.u32(static_cast<std::uint32_t>(pixmap.width));
        out.u32(static_cast<std::uint32_t>(pixmap.height));
        out.u32(static_cast<std::uint32_t>(pixmap.rowBytes));
        out.u32(static_cast<std::uint32_t>(pixmap.pixelSize));
        out.choice(kPixelTypes, static_cast<std::uint32_t>(pixmap.pixelType));
        out.choice(kEndians, static_cast<std::uint32_t>(pixmap.bitOrder));
        out.choice(kEndians, static_cast<std::uint32_t>(pixmap.byteOrder));
        out.rawData(image.data(), image.size());
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
