// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Texture shaders and textures in 3DMF files ('txsu' TextureShader with
// 'shdr' ShaderData and 'sduv' ShaderUVTransform, 'txpm' PixmapTexture,
// 'txmm' MipmapTexture): written and read back in every encoding and mode
// and compared field by field and image byte by byte; a texture shared by
// two shaders read back as one object; files written by hand in text and
// both byte orders (tests/data/textures*.3dmf, make_texture_binary.py);
// malformed variants as file errors.

#include "FileTestSupport.h"
#include "Q3ApiTest.h"
#include "TextureTestSupport.h"

#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

using namespace q3test;

namespace {

class FileTextureTest : public Q3ApiTest {};

const TQ3FileMode kModes[] = {kQ3FileModeNormal, kQ3FileModeText, kQ3FileModeStream | kQ3FileModeText,
                              kQ3FileModeDatabase};

std::vector<unsigned char> dataFile(const char* name)
{
    std::ifstream in(std::string(Q3_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<unsigned char> storageBytes(TQ3StorageObject storage, unsigned long offset, unsigned long size)
{
    std::vector<unsigned char> bytes(size);
    unsigned long read = 0;
    if (size > 0)
        EXPECT_EQ(Q3Storage_GetData(storage, offset, size, bytes.data(), &read), kQ3Success);
    EXPECT_EQ(read, size);
    return bytes;
}

// What a texture holds, as its Get calls give it: the pixmap fields or the
// mipmap's, and each image's rows (without their padding).
struct TextureFacts {
    TQ3ObjectType type = 0;
    unsigned long width = 0, height = 0, pixelSize = 0;
    long pixelType = -1, bitOrder = -1, byteOrder = -1, useMipmapping = -1;
    std::vector<std::vector<unsigned char>> rows; // every image's rows in turn

    bool operator==(const TextureFacts& o) const
    {
        return type == o.type && width == o.width && height == o.height && pixelSize == o.pixelSize &&
               pixelType == o.pixelType && bitOrder == o.bitOrder && byteOrder == o.byteOrder &&
               useMipmapping == o.useMipmapping && rows == o.rows;
    }
};

unsigned long bytesPerPixel(long type)
{
    return type == kQ3PixelTypeRGB24 ? 3 : (type == kQ3PixelTypeRGB32 || type == kQ3PixelTypeARGB32) ? 4 : 2;
}

TextureFacts factsOf(TQ3TextureObject texture)
{
    TextureFacts f;
    f.type = Q3Texture_GetType(texture);
    if (f.type == kQ3TextureTypePixmap) {
        TQ3StoragePixmap p{};
        EXPECT_EQ(Q3PixmapTexture_GetPixmap(texture, &p), kQ3Success);
        f.width = p.width;
        f.height = p.height;
        f.pixelSize = p.pixelSize;
        f.pixelType = p.pixelType;
        f.bitOrder = p.bitOrder;
        f.byteOrder = p.byteOrder;
        for (unsigned long y = 0; y < p.height; ++y)
            f.rows.push_back(storageBytes(p.image, y * p.rowBytes, p.width * bytesPerPixel(p.pixelType)));
        Q3Object_Dispose(p.image);
    } else {
        TQ3Mipmap m{};
        EXPECT_EQ(Q3MipmapTexture_GetMipmap(texture, &m), kQ3Success);
        f.width = m.mipmaps[0].width;
        f.height = m.mipmaps[0].height;
        f.pixelType = m.pixelType;
        f.bitOrder = m.bitOrder;
        f.byteOrder = m.byteOrder;
        f.useMipmapping = m.useMipmapping;
        unsigned levels = 1;
        if (m.useMipmapping == kQ3True)
            for (unsigned long side = std::max(f.width, f.height); side > 1; side >>= 1)
                ++levels;
        for (unsigned i = 0; i < levels; ++i) {
            const TQ3MipmapImage& image = m.mipmaps[i];
            for (unsigned long y = 0; y < image.height; ++y)
                f.rows.push_back(storageBytes(m.image, image.offset + y * image.rowBytes,
                                              image.width * bytesPerPixel(m.pixelType)));
        }
        Q3Object_Dispose(m.image);
    }
    return f;
}

struct ShaderFacts {
    long uBoundary = -1, vBoundary = -1;
    TQ3Matrix3x3 transform{};
    TQ3TextureObject texture = nullptr; // a borrowed handle, for identity
    TextureFacts textureFacts;
};

ShaderFacts shaderFactsOf(TQ3Object shader)
{
    ShaderFacts f;
    EXPECT_EQ(Q3SurfaceShader_GetType(shader), kQ3SurfaceShaderTypeTexture);
    TQ3ShaderUVBoundary u = kQ3ShaderUVBoundaryWrap, v = kQ3ShaderUVBoundaryWrap;
    EXPECT_EQ(Q3Shader_GetUBoundary(shader, &u), kQ3Success);
    EXPECT_EQ(Q3Shader_GetVBoundary(shader, &v), kQ3Success);
    f.uBoundary = u;
    f.vBoundary = v;
    EXPECT_EQ(Q3Shader_GetUVTransform(shader, &f.transform), kQ3Success);
    EXPECT_EQ(Q3TextureShader_GetTexture(shader, &f.texture), kQ3Success);
    f.textureFacts = factsOf(f.texture);
    Q3Object_Dispose(f.texture); // the shader keeps it alive
    return f;
}

bool sameMatrix(const TQ3Matrix3x3& a, const TQ3Matrix3x3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// A 3 x 2 RGB24 pixmap texture (rows of 10 bytes) shader, u clamped, a uv
// transform; and a 4 x 4 ARGB16 mipmap shader with its chain at odd offsets.
struct Made {
    TQ3StorageObject pixmapStorage = nullptr, mipmapStorage = nullptr;
    TQ3TextureObject pixmapTexture = nullptr, mipmapTexture = nullptr;
    TQ3ShaderObject pixmapShader = nullptr, mipmapShader = nullptr;

    Made()
    {
        std::vector<unsigned char> pixels(20);
        for (std::size_t i = 0; i < pixels.size(); ++i)
            pixels[i] = static_cast<unsigned char>(17 * i + 3);
        pixmapStorage = Q3MemoryStorage_New(pixels.data(), 20);
        const TQ3StoragePixmap pixmap{pixmapStorage, 3, 2, 10, 24, kQ3PixelTypeRGB24, kQ3EndianBig, kQ3EndianLittle};
        pixmapTexture = Q3PixmapTexture_New(&pixmap);
        pixmapShader = Q3TextureShader_New(pixmapTexture);
        Q3Shader_SetUBoundary(pixmapShader, kQ3ShaderUVBoundaryClamp);
        TQ3Matrix3x3 m{{{0.5f, 0.25f, 0}, {-1, 2, 0}, {0.125f, 3, 1}}};
        Q3Shader_SetUVTransform(pixmapShader, &m);

        std::vector<unsigned char> chain(100);
        for (std::size_t i = 0; i < chain.size(); ++i)
            chain[i] = static_cast<unsigned char>(29 * i + 7);
        mipmapStorage = Q3MemoryStorage_New(chain.data(), 100);
        const TQ3Mipmap mipmap = q3test::bigEndianMipmap(mipmapStorage, kQ3PixelTypeARGB16, true,
                                                         {{4, 4, 10, 2}, {2, 2, 6, 50}, {1, 1, 2, 90}});
        mipmapTexture = Q3MipmapTexture_New(&mipmap);
        mipmapShader = Q3TextureShader_New(mipmapTexture);
        Q3Shader_SetVBoundary(mipmapShader, kQ3ShaderUVBoundaryClamp);
    }
    ~Made()
    {
        for (TQ3Object o : {pixmapShader, mipmapShader, pixmapTexture, mipmapTexture, pixmapStorage, mipmapStorage})
            Q3Object_Dispose(o);
    }
};

TEST_F(FileTextureTest, ShadersAndTexturesRoundTripInEveryEncodingAndMode)
{
    Made made;
    ASSERT_NE(made.pixmapShader, nullptr);
    ASSERT_NE(made.mipmapShader, nullptr);
    const ShaderFacts pixmapFacts = shaderFactsOf(made.pixmapShader);
    const ShaderFacts mipmapFacts = shaderFactsOf(made.mipmapShader);
    for (TQ3FileMode mode : kModes) {
        const std::vector<TQ3Object> read =
            readAll(writeObjects({made.pixmapShader, made.mipmapShader, made.mipmapTexture}, mode));
        ASSERT_EQ(read.size(), 3u) << "mode " << mode;
        const ShaderFacts first = shaderFactsOf(read[0]);
        const ShaderFacts second = shaderFactsOf(read[1]);
        EXPECT_EQ(first.uBoundary, pixmapFacts.uBoundary) << "mode " << mode;
        EXPECT_EQ(first.vBoundary, pixmapFacts.vBoundary) << "mode " << mode;
        EXPECT_TRUE(sameMatrix(first.transform, pixmapFacts.transform)) << "mode " << mode;
        EXPECT_TRUE(first.textureFacts == pixmapFacts.textureFacts) << "mode " << mode;
        EXPECT_EQ(second.vBoundary, kQ3ShaderUVBoundaryClamp) << "mode " << mode;
        EXPECT_TRUE(sameMatrix(second.transform, mipmapFacts.transform)) << "mode " << mode;
        EXPECT_TRUE(second.textureFacts == mipmapFacts.textureFacts) << "mode " << mode;
        // The texture written on its own after its shader: one object when
        // the file refers to it (not in a stream, which repeats it).
        EXPECT_EQ(Q3Texture_GetType(read[2]), kQ3TextureTypeMipmap);
        EXPECT_TRUE(factsOf(read[2]) == mipmapFacts.textureFacts) << "mode " << mode;
        if ((mode & kQ3FileModeStream) == 0)
            EXPECT_EQ(read[2], second.texture) << "mode " << mode;
        else
            EXPECT_NE(read[2], second.texture) << "mode " << mode;
        disposeAll(read);
    }
}

TEST_F(FileTextureTest, HandWrittenFilesReadInTextAndBothByteOrders)
{
    for (const char* name : {"textures.3dmf", "textures_be.3dmf", "textures_le.3dmf"}) {
        const std::vector<unsigned char> bytes = dataFile(name);
        ASSERT_FALSE(bytes.empty()) << name;
        const std::vector<TQ3Object> read = readAll(bytes);
        ASSERT_EQ(read.size(), 2u) << name;
        const ShaderFacts first = shaderFactsOf(read[0]);
        EXPECT_EQ(first.uBoundary, kQ3ShaderUVBoundaryClamp) << name;
        EXPECT_EQ(first.vBoundary, kQ3ShaderUVBoundaryWrap) << name;
        const TQ3Matrix3x3 doubled{{{2, 0, 0}, {0, 1, 0}, {0.25f, 0, 1}}};
        EXPECT_TRUE(sameMatrix(first.transform, doubled)) << name;
        const TextureFacts& p = first.textureFacts;
        EXPECT_EQ(p.type, kQ3TextureTypePixmap) << name;
        EXPECT_EQ(p.width, 2u);
        EXPECT_EQ(p.height, 2u);
        EXPECT_EQ(p.pixelSize, 32u);
        EXPECT_EQ(p.pixelType, kQ3PixelTypeARGB32);
        ASSERT_EQ(p.rows.size(), 2u);
        EXPECT_EQ(p.rows[0], std::vector<unsigned char>({0xFF, 0xFF, 0, 0, 0xFF, 0, 0xFF, 0})) << name;
        EXPECT_EQ(p.rows[1], std::vector<unsigned char>({0xFF, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF})) << name;

        const ShaderFacts second = shaderFactsOf(read[1]);
        EXPECT_EQ(second.uBoundary, kQ3ShaderUVBoundaryWrap) << name;
        const TextureFacts& m = second.textureFacts;
        EXPECT_EQ(m.type, kQ3TextureTypeMipmap) << name;
        EXPECT_EQ(m.useMipmapping, kQ3True);
        EXPECT_EQ(m.pixelType, kQ3PixelTypeRGB16);
        EXPECT_EQ(m.byteOrder, kQ3EndianLittle);
        EXPECT_EQ(m.width, 4u);
        EXPECT_EQ(m.height, 2u);
        // 4 x 2 after the 4 offset bytes, then 2 x 1 and 1 x 1.
        ASSERT_EQ(m.rows.size(), 4u) << name;
        EXPECT_EQ(m.rows[0], std::vector<unsigned char>({0, 0, 0x1F, 0, 0xE0, 0x03, 0, 0x7C})) << name;
        EXPECT_EQ(m.rows[1], std::vector<unsigned char>({0xFF, 0x7F, 0, 0, 0x1F, 0, 0xE0, 0x03})) << name;
        EXPECT_EQ(m.rows[2], std::vector<unsigned char>({0, 0x7C, 0x1F, 0})) << name;
        EXPECT_EQ(m.rows[3], std::vector<unsigned char>({0xE0, 0x03})) << name;
        disposeAll(read);
    }
}

std::string textFile()
{
    const std::vector<unsigned char> bytes = dataFile("textures.3dmf");
    return std::string(bytes.begin(), bytes.end());
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
        text.replace(at, from.size(), to);
    return text;
}

TEST_F(FileTextureTest, MalformedTexturesAreFileErrors)
{
    const std::string text = textFile();
    const std::pair<std::string, std::string> broken[] = {
        // The pixmap's image one byte short, one byte long.
        {"0xFFFF0000FF00FF0000000000FF0000FFFFFFFFFF00000000", "0xFFFF0000FF00FF0000000000FF0000FFFFFFFFFF000000"},
        {"0xFFFF0000FF00FF0000000000FF0000FFFFFFFFFF00000000", "0xFFFF0000FF00FF0000000000FF0000FFFFFFFFFF0000000000"},
        // Words outside their enumerations.
        {"ARGB32 BigEndian", "ARGB64 BigEndian"},
        {"ShaderData ( Clamp Wrap )", "ShaderData ( Clamp Repeat )"},
        {"True RGB16", "Maybe RGB16"},
        // The API's rules: pixelSize, rowBytes, a side past the limit, a
        // chain whose first image is not a power of 2.
        {"2 2 12 32", "2 2 12 16"},
        {"2 2 12 32", "2 2 7 32"},
        {"2 2 12 32", "4097 2 12 32"},
        {"4 2 8 4", "3 2 6 4"},
        {"4 2 8 4", "4294967295 2 8 4"},
        // A non-finite uv transform, a short ShaderData.
        {"ShaderUVTransform ( 2 0 0", "ShaderUVTransform ( 2 0 1e39"},
        {"ShaderData ( Clamp Wrap )", "ShaderData ( Clamp )"},
        // A shader without its texture, a shader with two.
        {"  MipmapTexture (", "  UnknownThing ("},
    };
    int i = 0;
    for (const auto& [from, to] : broken) {
        const std::string bad = replaced(text, from, to);
        EXPECT_NE(readError(bytesOf(bad)), kQ3ErrorNone) << "variant " << i;
        forgetPosted();
        ++i;
    }
    // Two textures in one shader.
    const std::string twice =
        replaced(text, "  ShaderData ( Clamp Wrap )", "  PixmapTexture ( 1 1 4 32 ARGB32 BigEndian BigEndian 0xFF000000 )\n  ShaderData ( Clamp Wrap )");
    EXPECT_READ_ERROR(bytesOf(twice), kQ3ErrorInvalidMetafileObject);
    // ShaderData on its own.
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Normal )\nShaderData ( Wrap Wrap )\n"), kQ3ErrorInvalidMetafileObject);
    // A TextureShader with no container: no texture.
    EXPECT_READ_ERROR(bytesOf("3DMetafile ( 1 6 Normal )\nTextureShader ( )\n"), kQ3ErrorInvalidMetafileObject);
}

TEST_F(FileTextureTest, BinaryFilesCutShortAreFileErrors)
{
    const std::vector<unsigned char> whole = dataFile("textures_be.3dmf");
    ASSERT_GT(whole.size(), 40u);
    for (std::size_t cut : {whole.size() - 1, whole.size() - 4, std::size_t(60), std::size_t(40)}) {
        const std::vector<unsigned char> part(whole.begin(), whole.begin() + cut);
        EXPECT_NE(readError(part), kQ3ErrorNone) << "cut at " << cut;
        forgetPosted();
    }
}

} // namespace
