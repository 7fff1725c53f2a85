// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Textures and the texture shader (3D Metafile Reference, "Shader objects";
// the layouts Apple's and Quesa's files use):
//   'txpm' PixmapTexture: width height rowBytes pixelSize (Uns32), pixelType
//     (RGB32 ARGB32 RGB16 ARGB16 RGB16_565 RGB24), bitOrder byteOrder
//     (BigEndian LittleEndian), then rowBytes * height bytes of image (raw
//     data: padded with zeros to a multiple of 4 in binary, one 0x... token in
//     text);
//   'txmm' MipmapTexture: useMipmapping (False True), pixelType, bitOrder,
//     byteOrder, then the first image's width height rowBytes offset (Uns32),
//     then the image data: offset bytes, the first image (rowBytes * height),
//     and with useMipmapping every next image, halving down to 1 x 1, rows
//     packed (width * bytes per pixel), one after another;
//   'txsu' TextureShader: no data; in its container, in any order, its
//     texture (a PixmapTexture, a MipmapTexture or a Reference to one:
//     required), 'shdr' ShaderData ( uBoundary vBoundary: Wrap Clamp ) and
//     'sduv' ShaderUVTransform (a 3 x 3 matrix, row by row). Other
//     subobjects (the 4 x 4 'sdxf' ShaderTransform Q3 has no use for) are
//     skipped.
// Images go into new memory storages; every object is built through its
// class's checks, so a file cannot make a texture the API would refuse.

#include "io/ClassIO.h"
#include "io/PixmapIO.h"

#include "core/Limits.h"
#include "base/Storage.h"
#include "shader/TextureShader.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace q3::io {
namespace {

constexpr TQ3ObjectType kTypeShaderData = Q3_OBJECT_TYPE('s', 'h', 'd', 'r');
constexpr TQ3ObjectType kTypeShaderUVTransform = Q3_OBJECT_TYPE('s', 'd', 'u', 'v');

const std::vector<std::pair<const char*, std::uint32_t>> kBooleans = {{"False", kQ3False}, {"True", kQ3True}};
const std::vector<std::pair<const char*, std::uint32_t>> kBoundaries = {{"Wrap", kQ3ShaderUVBoundaryWrap},
                                                                        {"Clamp", kQ3ShaderUVBoundaryClamp}};

std::uint32_t bytesPerPixel(std::uint32_t pixelType)
{
    return pixelType == kQ3PixelTypeRGB24 ? 3 : (pixelType == kQ3PixelTypeRGB32 || pixelType == kQ3PixelTypeARGB32) ? 4 : 2;
}

void requireEnd(const DataReader& in, const char* what)
{
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, std::string("a ") + what + " has more data than its fields");
}

// Builds through the class's rules; a broken rule is the file's error.
template <class T, class Data>
Ref<SharedObject> build(const char* what, const Data& data)
{
    try {
        return Ref<SharedObject>(makeShared<T>(data));
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidMetafileObject, std::string("the file's ") + what + " breaks a rule: " + error.what());
    }
}

// `size` bytes of a texture's storage from `offset`.
std::vector<unsigned char> readStorage(TQ3StorageObject image, std::size_t offset, std::size_t size)
{
    std::vector<unsigned char> bytes(size);
    const auto& storage = static_cast<const Storage&>(*static_cast<const Object*>(image));
    if (storage.size() < offset || storage.read(offset, size, bytes.data()) < size)
        fail(kQ3ErrorInvalidData, "the texture's storage now holds fewer bytes than its image needs");
    return bytes;
}

Ref<SharedObject> readPixmapTexture(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3StoragePixmap pixmap{};
    const std::string image = readPixmapFields(in, pixmap);
    requireEnd(in, "PixmapTexture");
    Ref<MemoryStorage> storage = storageOf(image);
    pixmap.image = storage.get();
    return build<PixmapTexture>("PixmapTexture", pixmap);
}

void writePixmapTexture(WriteContext& context, const Object& object)
{
    const TQ3StoragePixmap pixmap = static_cast<const PixmapTexture&>(object).pixmap();
    const Ref<Storage> held = Ref<Storage>::adopt(static_cast<Storage*>(static_cast<Object*>(pixmap.image)));
    const std::vector<unsigned char> image = readStorage(pixmap.image, 0, std::size_t{pixmap.rowBytes} * pixmap.height);
    Encoder& out = context.out();
    out.begin(kQ3TextureTypePixmap, "PixmapTexture");
    writePixmapFields(out, pixmap, image);
    out.end();
}

Ref<SharedObject> readMipmapTexture(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3Mipmap mipmap{};
    mipmap.useMipmapping = static_cast<TQ3Boolean>(in.choice(kBooleans));
    const std::uint32_t pixelType = in.choice(kPixelTypes);
    mipmap.pixelType = static_cast<TQ3PixelType>(pixelType);
    mipmap.bitOrder = static_cast<TQ3Endian>(in.choice(kEndians));
    mipmap.byteOrder = static_cast<TQ3Endian>(in.choice(kEndians));
    TQ3MipmapImage& first = mipmap.mipmaps[0];
    first.width = in.u32();
    first.height = in.u32();
    first.rowBytes = in.u32();
    first.offset = in.u32();
    // The chain's layout follows from the first image; sizes past the API's
    // limit are refused before the chain is worked out.
    if (first.width > limits::kMaxTextureSize || first.height > limits::kMaxTextureSize)
        fail(kQ3ErrorInvalidMetafileObject, "a MipmapTexture of " + std::to_string(first.width) + " x " +
                                                std::to_string(first.height) + " pixels is larger than " +
                                                std::to_string(limits::kMaxTextureSize) + " a side");
    std::uint64_t size = std::uint64_t{first.offset} + std::uint64_t{first.rowBytes} * first.height;
    const unsigned count = MipmapTexture::imageCount(mipmap);
    for (unsigned i = 1; i < count; ++i) {
        TQ3MipmapImage& image = mipmap.mipmaps[i];
        image.width = std::max(1ul, first.width >> i);
        image.height = std::max(1ul, first.height >> i);
        image.rowBytes = image.width * bytesPerPixel(pixelType);
        image.offset = static_cast<unsigned long>(size);
        size += std::uint64_t{image.rowBytes} * image.height;
    }
    in.requireRoom(size, 1, 0, "image bytes");
    const std::string bytes = in.rawData(static_cast<std::size_t>(size));
    requireEnd(in, "MipmapTexture");
    Ref<MemoryStorage> storage = storageOf(bytes);
    mipmap.image = storage.get();
    return build<MipmapTexture>("MipmapTexture", mipmap);
}

void writeMipmapTexture(WriteContext& context, const Object& object)
{
    const TQ3Mipmap mipmap = static_cast<const MipmapTexture&>(object).mipmap();
    const Ref<Storage> held = Ref<Storage>::adopt(static_cast<Storage*>(static_cast<Object*>(mipmap.image)));
    const std::uint32_t pixelType = static_cast<std::uint32_t>(mipmap.pixelType);
    const TQ3MipmapImage& first = mipmap.mipmaps[0];
    // The first image as it is, then the others' rows packed.
    std::vector<unsigned char> bytes = readStorage(mipmap.image, first.offset, std::size_t{first.rowBytes} * first.height);
    const unsigned count = MipmapTexture::imageCount(mipmap);
    for (unsigned i = 1; i < count; ++i) {
        const TQ3MipmapImage& image = mipmap.mipmaps[i];
        const std::size_t row = std::size_t{image.width} * bytesPerPixel(pixelType);
        for (unsigned long y = 0; y < image.height; ++y) {
            const std::vector<unsigned char> line = readStorage(mipmap.image, image.offset + y * image.rowBytes, row);
            bytes.insert(bytes.end(), line.begin(), line.end());
        }
    }
    Encoder& out = context.out();
    out.begin(kQ3TextureTypeMipmap, "MipmapTexture");
    out.choice(kBooleans, static_cast<std::uint32_t>(mipmap.useMipmapping));
    out.choice(kPixelTypes, pixelType);
    out.choice(kEndians, static_cast<std::uint32_t>(mipmap.bitOrder));
    out.choice(kEndians, static_cast<std::uint32_t>(mipmap.byteOrder));
    out.u32(static_cast<std::uint32_t>(first.width));
    out.u32(static_cast<std::uint32_t>(first.height));
    out.u32(static_cast<std::uint32_t>(first.rowBytes));
    out.u32(0);
    out.rawData(bytes.data(), bytes.size());
    out.end();
}

Ref<SharedObject> readTextureShader(ReadContext& context, const Parts& parts)
{
    requireEnd(context.reader(parts.root), "TextureShader");
    Ref<Texture> texture;
    TQ3ShaderUVBoundary boundaries[2] = {kQ3ShaderUVBoundaryWrap, kQ3ShaderUVBoundaryWrap};
    TQ3Matrix3x3 transform{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (const Node* node : parts.subobjects) {
        if (node->type == kTypeShaderData) {
            DataReader in = context.reader(*node);
            for (TQ3ShaderUVBoundary& boundary : boundaries)
                boundary = static_cast<TQ3ShaderUVBoundary>(in.choice(kBoundaries));
            requireEnd(in, "ShaderData");
        } else if (node->type == kTypeShaderUVTransform) {
            DataReader in = context.reader(*node);
            for (auto& row : transform.value)
                for (float& value : row)
                    value = in.f32();
            requireEnd(in, "ShaderUVTransform");
        } else if (node->type == kQ3TextureTypePixmap || node->type == kQ3TextureTypeMipmap ||
                   node->type == kTypeReference || node->type == kTypeContainer) {
            if (texture)
                fail(kQ3ErrorInvalidMetafileObject, "a TextureShader has two textures");
            texture = context.objectAs<Texture>(*node, "a TextureShader's texture");
        }
    }
    if (!texture)
        fail(kQ3ErrorInvalidMetafileObject, "a TextureShader has no texture");
    Ref<TextureShader> shader = makeShared<TextureShader>(std::move(texture));
    shader->setUBoundary(boundaries[0]);
    shader->setVBoundary(boundaries[1]);
    try {
        shader->setUVTransform(transform);
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidMetafileObject, std::string("the file's ShaderUVTransform breaks a rule: ") + error.what());
    }
    return Ref<SharedObject>(std::move(shader));
}

void writeTextureShader(WriteContext& context, const Object& object)
{
    const auto& shader = static_cast<const TextureShader&>(object);
    Encoder& out = context.out();
    out.begin(kTypeContainer, "Container");
    out.begin(kQ3SurfaceShaderTypeTexture, "TextureShader");
    out.end();
    if (shader.uBoundary() != kQ3ShaderUVBoundaryWrap || shader.vBoundary() != kQ3ShaderUVBoundaryWrap) {
        out.begin(kTypeShaderData, "ShaderData");
        out.choice(kBoundaries, static_cast<std::uint32_t>(shader.uBoundary()));
        out.choice(kBoundaries, static_cast<std::uint32_t>(shader.vBoundary()));
        out.end();
    }
    const TQ3Matrix3x3& m = shader.uvTransform();
    const TQ3Matrix3x3 identity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    if (std::memcmp(&m, &identity, sizeof m) != 0) {
        out.begin(kTypeShaderUVTransform, "ShaderUVTransform");
        for (const auto& row : m.value)
            for (float value : row)
                out.f32(value);
        out.end();
    }
    context.object(*shader.texture());
    out.end();
}

Ref<SharedObject> refuseShaderPart(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject, typeName(parts.root.type) + " outside a shader");
}

void writeNothing(WriteContext&, const Object&) {}

} // namespace

void addTextureClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(), {
                                  {kQ3TextureTypePixmap, "PixmapTexture", readPixmapTexture, writePixmapTexture},
                                  {kQ3TextureTypeMipmap, "MipmapTexture", readMipmapTexture, writeMipmapTexture},
                                  {kQ3SurfaceShaderTypeTexture, "TextureShader", readTextureShader,
                                   writeTextureShader},
                                  {kTypeShaderData, "ShaderData", refuseShaderPart, writeNothing},
                                  {kTypeShaderUVTransform, "ShaderUVTransform", refuseShaderPart, writeNothing},
                              });
}

} // namespace q3::io
