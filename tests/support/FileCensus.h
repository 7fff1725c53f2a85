// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The census of a 3DMF file, through the public API only: what reading it
// gives, counted, so that two files can be compared for "nothing lost" (a
// file and what a round trip through another encoding made of it).
//
// Each line of the census is one fact, counted as often as it occurs:
//   "object box "                  an object of that leaf type was reached
//                                 (top level, inside a group, in a view
//                                 hints object, a highlight style, an
//                                 attribute set's surface shader)
//   "dspg  state 0x..."            a display group's state flags
//   "box  attributes 5,11"         the attribute types present in a
//                                 geometry's own set (the geometry's leaf
//                                 type, then the types, 1..11, ascending)
//   "box  face attributes 5"       one of a box's face sets
//   "trng vertex attributes 3,5"   one of a triangle's, polygon's or
//                                 polyline's vertex sets (a polyline's
//                                 segment sets: "segment attributes")
//   "attr attributes 5,6"          an attribute set reached as an object
//   "txsu texture txpm 4x4 ..."    a texture shader's texture: its size,
//                                 pixel type and a hash of its pixels
//   "unknown text Name: contents"  an unknown object (binary: its type,
//                                 size and a hash of its data)
// Types are written as their four characters ('box ', 'dspg').
//
// Q3AttributeSet_GetNextAttributeType is not in QD3DSet.h (yet), so the
// types present are found by probing Q3AttributeSet_Contains for each of
// kQ3AttributeTypeSurfaceUV .. kQ3AttributeTypeSurfaceShader; an element a
// file gave a set that Q3 has no class for is not seen.

#include "QD3D.h"
#include "QD3DErrors.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStorage.h"
#include "QD3DStyle.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace q3test {

struct Census {
    /// Every fact, with the number of times it occurs.
    std::map<std::string, int> lines;
    /// Objects read at the file's top level.
    int topLevel = 0;
    /// Empty when the whole file read; else what stopped the reading.
    std::string failure;

    bool operator==(const Census& other) const
    {
        return lines == other.lines && topLevel == other.topLevel && failure == other.failure;
    }
    bool operator!=(const Census& other) const { return !(*this == other); }
};

namespace census {

inline std::string fourCC(TQ3ObjectType type)
{
    std::string s;
    for (int shift = 24; shift >= 0; shift -= 8) {
        const char c = static_cast<char>((static_cast<std::uint32_t>(type) >> shift) & 0xFF);
        s += (c >= 32 && c < 127) ? c : '?';
    }
    return s;
}

inline std::string hex(std::uint64_t v)
{
    char buffer[24];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(v));
    return buffer;
}

/// FNV-1a, 64 bits, continued from `h`.
inline std::uint64_t fnv(const unsigned char* bytes, std::size_t n, std::uint64_t h = 0xcbf29ce484222325ull)
{
    for (std::size_t i = 0; i < n; ++i) {
        h ^= bytes[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

inline unsigned long bytesPerPixel(TQ3PixelType type)
{
    switch (type) {
    case kQ3PixelTypeRGB32:
    case kQ3PixelTypeARGB32:
        return 4;
    case kQ3PixelTypeRGB24:
        return 3;
    default:
        return 2;
    }
}

/// The hash of an image's pixels: of each of its rows, the width * bytes per
/// pixel that hold pixels (not the padding rowBytes may add), starting at
/// `offset` in the storage. "unreadable" when the storage is short.
inline std::string pixelHash(TQ3StorageObject storage, unsigned long offset, unsigned long width,
                             unsigned long height, unsigned long rowBytes, unsigned long bpp)
{
    unsigned long size = 0;
    if (storage == nullptr || Q3Storage_GetSize(storage, &size) != kQ3Success)
        return "no storage";
    std::vector<unsigned char> all(size);
    unsigned long got = 0;
    if (size > 0 && Q3Storage_GetData(storage, 0, size, all.data(), &got) != kQ3Success)
        return "unreadable";
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned long y = 0; y < height; ++y) {
        const unsigned long start = offset + y * rowBytes;
        if (start + width * bpp > got)
            return "short storage";
        h = fnv(all.data() + start, width * bpp, h);
    }
    return hex(h);
}

inline std::string attributeTypes(TQ3AttributeSet set)
{
    std::string types;
    for (TQ3AttributeType type = kQ3AttributeTypeSurfaceUV; type <= kQ3AttributeTypeSurfaceShader; ++type)
        if (Q3AttributeSet_Contains(set, type) == kQ3True)
            types += (types.empty() ? "" : ",") + std::to_string(type);
    return types.empty() ? "none" : types;
}

class Counter {
public:
    explicit Counter(Census& census) : m_census(census) {}

    void add(const std::string& line) { ++m_census.lines[line]; }

    void object(TQ3Object object, int depth = 0)
    {
        if (object == nullptr)
            return;
        if (depth > 64) {
            add("too deep");
            return;
        }
        const TQ3ObjectType leaf = Q3Object_GetLeafType(object);
        const std::string name = fourCC(leaf);
        add("object " + name);
        if (Q3Object_IsType(object, kQ3ShapeTypeGroup) == kQ3True)
            group(object, name, depth);
        else if (Q3Object_IsType(object, kQ3ShapeTypeGeometry) == kQ3True)
            geometry(object, leaf, name, depth);
        else if (Q3Object_IsType(object, kQ3SetTypeAttribute) == kQ3True)
            attributeSet(object, "attr attributes", depth);
        else if (Q3Object_IsType(object, kQ3SurfaceShaderTypeTexture) == kQ3True)
            textureShader(object, name);
        else if (Q3Object_IsType(object, kQ3SharedTypeViewHints) == kQ3True)
            viewHints(object, depth);
        else if (leaf == kQ3StyleTypeHighlight)
            highlight(object, depth);
        else if (Q3Object_IsType(object, kQ3ShapeTypeUnknown) == kQ3True)
            unknown(object);
    }

private:
    void group(TQ3GroupObject g, const std::string& name, int depth)
    {
        TQ3DisplayGroupState state = 0;
        if (Q3Object_IsType(g, kQ3GroupTypeDisplay) == kQ3True && Q3DisplayGroup_GetState(g, &state) == kQ3Success) {
            char buffer[16];
            std::snprintf(buffer, sizeof buffer, "0x%lx", static_cast<unsigned long>(state));
            add(name + " state " + buffer);
        }
        TQ3GroupPosition position = nullptr;
        if (Q3Group_GetFirstPosition(g, &position) != kQ3Success)
            return;
        while (position != nullptr) {
            TQ3Object child = nullptr;
            if (Q3Group_GetPositionObject(g, position, &child) == kQ3Success && child != nullptr) {
                object(child, depth + 1);
                Q3Object_Dispose(child);
            }
            if (Q3Group_GetNextPosition(g, &position) != kQ3Success)
                break;
        }
    }

    void attributeSet(TQ3AttributeSet set, const std::string& label, int depth)
    {
        if (set == nullptr)
            return;
        add(label + " " + attributeTypes(set));
        TQ3SurfaceShaderObject shader = nullptr;
        if (Q3AttributeSet_Contains(set, kQ3AttributeTypeSurfaceShader) == kQ3True &&
            Q3AttributeSet_Get(set, kQ3AttributeTypeSurfaceShader, &shader) == kQ3Success && shader != nullptr) {
            object(shader, depth + 1);
            Q3Object_Dispose(shader);
        }
    }

    void geometry(TQ3GeometryObject g, TQ3ObjectType leaf, const std::string& name, int depth)
    {
        TQ3AttributeSet own = nullptr;
        if (Q3Geometry_GetAttributeSet(g, &own) == kQ3Success && own != nullptr) {
            attributeSet(own, name + " attributes", depth);
            Q3Object_Dispose(own);
        }
        if (leaf == kQ3GeometryTypeBox) {
            TQ3BoxData data;
            if (Q3Box_GetData(g, &data) == kQ3Success) {
                for (int face = 0; face < 6 && data.faceAttributeSet != nullptr; ++face)
                    attributeSet(data.faceAttributeSet[face], name + " face attributes", depth);
                Q3Box_EmptyData(&data);
            }
        } else if (leaf == kQ3GeometryTypeTriangle) {
            TQ3TriangleData data;
            if (Q3Triangle_GetData(g, &data) == kQ3Success) {
                for (const TQ3Vertex3D& vertex : data.vertices)
                    attributeSet(vertex.attributeSet, name + " vertex attributes", depth);
                Q3Triangle_EmptyData(&data);
            }
        } else if (leaf == kQ3GeometryTypePolygon) {
            TQ3PolygonData data;
            if (Q3Polygon_GetData(g, &data) == kQ3Success) {
                for (unsigned long i = 0; i < data.numVertices; ++i)
                    attributeSet(data.vertices[i].attributeSet, name + " vertex attributes", depth);
                Q3Polygon_EmptyData(&data);
            }
        } else if (leaf == kQ3GeometryTypePolyLine) {
            TQ3PolyLineData data;
            if (Q3PolyLine_GetData(g, &data) == kQ3Success) {
                for (unsigned long i = 0; i < data.numVertices; ++i)
                    attributeSet(data.vertices[i].attributeSet, name + " vertex attributes", depth);
                for (unsigned long i = 0; data.segmentAttributeSet != nullptr && i + 1 < data.numVertices; ++i)
                    attributeSet(data.segmentAttributeSet[i], name + " segment attributes", depth);
                Q3PolyLine_EmptyData(&data);
            }
        }
    }

    void textureShader(TQ3ShaderObject shader, const std::string& name)
    {
        TQ3TextureObject texture = nullptr;
        if (Q3TextureShader_GetTexture(shader, &texture) != kQ3Success || texture == nullptr) {
            add(name + " texture none");
            return;
        }
        const TQ3ObjectType type = Q3Texture_GetType(texture);
        std::string line = name + " texture " + fourCC(type);
        if (type == kQ3TextureTypePixmap) {
            TQ3StoragePixmap pixmap;
            if (Q3PixmapTexture_GetPixmap(texture, &pixmap) == kQ3Success) {
                line += " " + std::to_string(pixmap.width) + "x" + std::to_string(pixmap.height) + " type " +
                        std::to_string(pixmap.pixelType) + " pixels " +
                        pixelHash(pixmap.image, 0, pixmap.width, pixmap.height, pixmap.rowBytes,
                                  bytesPerPixel(pixmap.pixelType));
                if (pixmap.image != nullptr)
                    Q3Object_Dispose(pixmap.image);
            }
        } else if (type == kQ3TextureTypeMipmap) {
            TQ3Mipmap mipmap;
            if (Q3MipmapTexture_GetMipmap(texture, &mipmap) == kQ3Success) {
                line += " type " + std::to_string(mipmap.pixelType) +
                        (mipmap.useMipmapping == kQ3True ? " mipmapped" : " one image");
                const int levels = mipmap.useMipmapping == kQ3True ? 32 : 1;
                for (int i = 0; i < levels && mipmap.mipmaps[i].width > 0; ++i) {
                    const TQ3MipmapImage& image = mipmap.mipmaps[i];
                    line += " " + std::to_string(image.width) + "x" + std::to_string(image.height) + ":" +
                            pixelHash(mipmap.image, image.offset, image.width, image.height, image.rowBytes,
                                      bytesPerPixel(mipmap.pixelType));
                    if (image.width == 1 && image.height == 1)
                        break;
                }
                if (mipmap.image != nullptr)
                    Q3Object_Dispose(mipmap.image);
            }
        }
        add(line);
        Q3Object_Dispose(texture);
    }

    void viewHints(TQ3ViewHintsObject hints, int depth)
    {
        TQ3Object part = nullptr;
        if (Q3ViewHints_GetRenderer(hints, &part) == kQ3Success && part != nullptr) {
            object(part, depth + 1);
            Q3Object_Dispose(part);
        }
        part = nullptr;
        if (Q3ViewHints_GetCamera(hints, &part) == kQ3Success && part != nullptr) {
            object(part, depth + 1);
            Q3Object_Dispose(part);
        }
        part = nullptr;
        if (Q3ViewHints_GetLightGroup(hints, &part) == kQ3Success && part != nullptr) {
            object(part, depth + 1);
            Q3Object_Dispose(part);
        }
        part = nullptr;
        if (Q3ViewHints_GetAttributeSet(hints, &part) == kQ3Success && part != nullptr) {
            attributeSet(part, "vwhn attributes", depth);
            Q3Object_Dispose(part);
        }
    }

    void highlight(TQ3StyleObject style, int depth)
    {
        TQ3AttributeSet set = nullptr;
        if (Q3HighlightStyle_Get(style, &set) == kQ3Success && set != nullptr) {
            attributeSet(set, "high attributes", depth);
            Q3Object_Dispose(set);
        }
    }

    void unknown(TQ3UnknownObject object)
    {
        if (Q3Unknown_GetType(object) == kQ3UnknownTypeText) {
            TQ3UnknownTextData data = {nullptr, nullptr};
            if (Q3UnknownText_GetData(object, &data) == kQ3Success) {
                add(std::string("unknown text ") + (data.objectName ? data.objectName : "") + ": " +
                    (data.contents ? data.contents : ""));
                Q3UnknownText_EmptyData(&data);
            }
        } else {
            TQ3UnknownBinaryData data = {0, 0, kQ3EndianBig, nullptr};
            if (Q3UnknownBinary_GetData(object, &data) == kQ3Success) {
                add("unknown binary " + fourCC(data.objectType) + " size " + std::to_string(data.size) + " data " +
                    hex(fnv(reinterpret_cast<const unsigned char*>(data.contents), data.contents ? data.size : 0)));
                Q3UnknownBinary_EmptyData(&data);
            }
        }
    }

    Census& m_census;
};

} // namespace census

/// The census of objects in memory, as if they were a file's top-level
/// objects in this order: what a file written from them should give.
inline Census censusOfObjects(const std::vector<TQ3Object>& objects)
{
    Census result;
    census::Counter counter(result);
    for (TQ3Object object : objects) {
        ++result.topLevel;
        counter.object(object);
    }
    return result;
}

/// The census of the 3DMF file in `bytes` (see the top of this file).
inline Census censusOf(const std::vector<unsigned char>& bytes)
{
    Census result;
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size()));
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    Q3Object_Dispose(storage);
    TQ3FileMode mode = 0;
    if (Q3File_OpenRead(file, &mode) != kQ3Success) {
        result.failure = std::string("OpenRead: ") + Q3Error_GetMessage();
        Q3Object_Dispose(file);
        return result;
    }
    census::Counter counter(result);
    while (Q3File_IsEndOfFile(file) == kQ3False) {
        TQ3Object object = Q3File_ReadObject(file);
        if (object == nullptr) {
            result.failure = std::string("ReadObject: ") + Q3Error_GetMessage();
            break;
        }
        ++result.topLevel;
        counter.object(object);
        Q3Object_Dispose(object);
    }
    Q3File_Close(file);
    Q3Object_Dispose(file);
    return result;
}

/// The bytes of the file at `path` (none when it cannot be opened).
inline std::vector<unsigned char> fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The census of the 3DMF file at `path` (failure says so when it cannot be opened).
inline Census censusOfFile(const std::string& path)
{
    if (!std::ifstream(path, std::ios::binary)) {
        Census missing;
        missing.failure = "cannot open " + path;
        return missing;
    }
    return censusOf(fileBytes(path));
}

/// The lines in which two censuses differ ("- line xN" only in a, "+ line
/// xN" only in b), for a failure message.
inline std::string censusDifference(const Census& a, const Census& b)
{
    std::ostringstream out;
    if (a.topLevel != b.topLevel)
        out << "top-level objects: " << a.topLevel << " then " << b.topLevel << "\n";
    if (a.failure != b.failure)
        out << "failure: '" << a.failure << "' then '" << b.failure << "'\n";
    for (const auto& [line, n] : a.lines) {
        const auto it = b.lines.find(line);
        const int m = it == b.lines.end() ? 0 : it->second;
        if (m < n)
            out << "- " << line << " x" << (n - m) << "\n";
    }
    for (const auto& [line, m] : b.lines) {
        const auto it = a.lines.find(line);
        const int n = it == a.lines.end() ? 0 : it->second;
        if (n < m)
            out << "+ " << line << " x" << (m - n) << "\n";
    }
    return out.str();
}

/// Every line of a census, for a trace.
inline std::string censusText(const Census& c)
{
    std::ostringstream out;
    out << c.topLevel << " top-level objects" << (c.failure.empty() ? "" : ", then " + c.failure) << "\n";
    for (const auto& [line, n] : c.lines)
        out << "  " << line << " x" << n << "\n";
    return out.str();
}

} // namespace q3test
