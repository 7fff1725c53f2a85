// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// What every geometry decomposes into: points, line segments, line strips and
// triangles over one pool of vertices, each vertex with the attributes the
// renderers use (QD3DSet.h's diffuse colour, transparency colour, normal and
// surface uv), and each triangle with the surface shader its attribute sets
// give it. Rendering, bounding and Q3Geometry_GetDecomposed all consume this
// one form, through PrimitiveSink.

#include "QD3D.h"
#include "QD3DSet.h"
#include "core/Object.h"
#include "core/Ref.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace q3 {

class AttributeSet;

/// The attributes one vertex carries after inheritance. A component that is
/// NaN means "none here": the vertex takes that attribute from what is drawn
/// around it (its geometry's attribute set, then the view's state).
struct VertexAttributes {
    static constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

    TQ3ColorRGB color{kNone, kNone, kNone};
    TQ3ColorRGB transparency{kNone, kNone, kNone};
    TQ3Vector3D normal{kNone, kNone, kNone};
    /// The surface uv; where the vertex, its face and its geometry have
    /// none, the shading uv (uvIsShading), which a surface uv met later in
    /// the inheritance replaces.
    TQ3Param2D uv{kNone, kNone};
    bool uvIsShading = false;
    /// The surface shader (kQ3AttributeTypeSurfaceShader: a texture shader)
    /// of the vertex's own set, else of its face's; null for none. Borrowed
    /// from the sets while the mesh is built (Mesh keeps a reference).
    const SharedObject* shader = nullptr;

    bool hasColor() const { return color.r == color.r; }
    bool hasTransparency() const { return transparency.r == transparency.r; }
    bool hasNormal() const { return normal.x == normal.x; }
    bool hasUV() const { return uv.u == uv.u; }
    bool hasShader() const { return shader != nullptr; }

    /// QuickDraw 3D's inheritance step: each attribute this lacks is taken
    /// from `set` (null: nothing). Call it from the most specific set (the
    /// vertex's) to the least (the face's, the geometry's).
    void inheritFrom(const AttributeSet* set);
    /// The same step for one attribute value of a standard type (as stored in
    /// a TriMesh attribute array: for the surface shader, a handle the
    /// geometry holds, or NULL for none); types the renderers do not use are
    /// ignored.
    void inherit(TQ3AttributeType type, const void* value);
};

/// A run of consecutive vertices drawn as one connected line strip.
struct Strip {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
};

/// The placement and size of an image drawn in screen space at the image of
/// one vertex: `height` rows of `rowBytes` bytes, top row first. Its top
/// left pixel is xOffset pixels right of and yOffset pixels below the pixel
/// the vertex projects to.
struct ScreenImage {
    std::uint32_t vertex = 0;
    long xOffset = 0;
    long yOffset = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::size_t rowBytes = 0;
};

/// A bitmap (a marker): pixel x of a row is bit x % 8 of byte x / 8, from
/// the most significant bit unless lsbFirst. Set bits are drawn in the
/// vertex's colour.
struct ScreenBitmap : ScreenImage {
    const unsigned char* bits = nullptr;
    bool lsbFirst = false;
};

/// A colour image (a pixmap marker): each pixel a word of pixelType's layout
/// (QD3DDrawContext.h) stored in byteOrder. Pixels keep their own colours;
/// one whose alpha is 0 is not drawn. The fields are valid (PixmapMarker's
/// rules).
struct ScreenPixmap : ScreenImage {
    TQ3PixelType pixelType = kQ3PixelTypeARGB32;
    TQ3Endian byteOrder = kQ3EndianBig;
    const unsigned char* bytes = nullptr;
};

/// A decomposition as a set of borrowed arrays. Attribute arrays are null
/// when no vertex has that attribute; otherwise they hold one entry per
/// vertex, NaN where a vertex has none (VertexAttributes). Indices refer to
/// the vertex pool.
struct MeshView {
    const float* positions = nullptr;    ///< x y z per vertex
    std::size_t vertexCount = 0;
    const float* colors = nullptr;       ///< r g b per vertex, or null
    const float* transparency = nullptr; ///< r g b per vertex, or null
    const float* normals = nullptr;      ///< x y z per vertex, or null
    const float* uvs = nullptr;          ///< u v per vertex, or null

    const std::uint32_t* points = nullptr; ///< one index per point
    std::size_t pointCount = 0;
    const std::uint32_t* lines = nullptr; ///< two indices per segment
    std::size_t lineCount = 0;
    const Strip* strips = nullptr;
    std::size_t stripCount = 0;
    const std::uint32_t* triangles = nullptr; ///< three indices per triangle
    std::size_t triangleCount = 0;
    /// Per triangle, the surface shader its attribute sets give it: 0 for
    /// none (it takes its geometry's, else the view's), k for shaders[k - 1].
    /// Null when no triangle has one of its own.
    const std::uint32_t* triangleShaders = nullptr;
    const Ref<SharedObject>* shaders = nullptr; ///< the distinct shaders triangleShaders names
    std::size_t shaderCount = 0;
    /// How the triangles look in a wireframe: two indices per edge (the
    /// outline of a polygon, not the diagonals its triangulation added).
    const std::uint32_t* edges = nullptr;
    std::size_t edgeCount = 0;
    /// Bitmaps drawn in screen space (ScreenBitmap).
    const ScreenBitmap* bitmaps = nullptr;
    std::size_t bitmapCount = 0;
    /// Colour images drawn in screen space (ScreenPixmap).
    const ScreenPixmap* pixmaps = nullptr;
    std::size_t pixmapCount = 0;
    /// A number that names these arrays' contents: two views with the same
    /// non-zero serial have the same vertices, attributes and primitives
    /// (a retained geometry's cached mesh, Mesh::setSerial), so a renderer
    /// may keep what it derived from them. 0: no such promise (a mesh built
    /// for one submit, or a view whose arrays were replaced).
    std::uint64_t serial = 0;
    /// With a serial: every vertex has a uv (no u is NaN), found when the
    /// serial was given, so that a renderer need not look again each frame.
    /// false: not known.
    bool uvsComplete = false;
};

/// A decomposition that owns its arrays: what retained geometries cache.
/// Invariant: every attribute array is empty or has one entry per vertex;
/// every index is below vertexCount(); the triangle shader array is empty or
/// has one entry per triangle, each at most the number of shaders, which
/// are distinct and each held by one reference.
class Mesh {
public:
    std::size_t vertexCount() const { return m_positions.size() / 3; }

    /// Appends a vertex and returns its index.
    std::uint32_t addVertex(const TQ3Point3D& position, const VertexAttributes& attributes);
    void reserveVertices(std::size_t count);
    /// Appends the vertex at t (0..1) of the way from vertex a to vertex b:
    /// position, colours, normal (renormalized) and uv interpolated linearly,
    /// an attribute either end lacks left out, the shader of the nearer end.
    /// Returns its index.
    std::uint32_t addBetween(std::uint32_t a, std::uint32_t b, double t);

    void addPoint(std::uint32_t v) { m_points.push_back(v); }
    void addLine(std::uint32_t a, std::uint32_t b);
    /// A strip over the vertices first .. first + count - 1.
    void addStrip(std::uint32_t first, std::uint32_t count) { m_strips.push_back(Strip{first, count}); }
    /// A triangle over three vertices. Its surface shader is the one at
    /// least two of its corners have (VertexAttributes::shader, "none"
    /// counting as one): a shader given to every vertex of a face, or to the
    /// face, shades the face; one given to some vertices only does not
    /// decide a triangle the others outvote. Corners that all differ give
    /// none (the geometry's, else the view's).
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    /// A triangle whose surface shader is `shader` (null: none), whatever its
    /// corners have (a decomposition copied triangle by triangle).
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const SharedObject* shader);
    void addEdge(std::uint32_t a, std::uint32_t b);
    /// Makes the edges every distinct side of every triangle (a mesh's
    /// wireframe), replacing any edges added before.
    void edgesFromTriangles();

    const std::vector<std::uint32_t>& triangles() const { return m_triangles; }
    const std::vector<float>& positions() const { return m_positions; }
    MeshView view() const;
    void clear();

    /// Names the mesh's present contents for its views (MeshView::serial):
    /// a new number from newSerial() once the mesh is built and will not
    /// change. A copy of the mesh, and the mesh after clear(), have none.
    /// (It also notes whether every vertex has a uv: MeshView::uvsComplete.)
    void setSerial(std::uint64_t serial);
    /// A number no mesh was given before (never 0).
    static std::uint64_t newSerial();

private:
    // MeshView::serial; copied as 0 (a copy may be changed).
    struct Serial {
        std::uint64_t value = 0;
        bool uvsComplete = false;
        Serial() = default;
        Serial(const Serial&) noexcept {}
        Serial& operator=(const Serial&) noexcept
        {
            value = 0;
            uvsComplete = false;
            return *this;
        }
    };
    Serial m_serial;
    std::vector<float> m_positions;
    std::vector<float> m_colors;
    std::vector<float> m_transparency;
    std::vector<float> m_normals;
    std::vector<float> m_uvs;
    std::vector<std::uint32_t> m_points;
    std::vector<std::uint32_t> m_lines;
    std::vector<Strip> m_strips;
    std::vector<std::uint32_t> m_triangles;
    std::vector<std::uint32_t> m_edges;
    /// The surface shaders: distinct, referenced; the per-vertex and
    /// per-triangle arrays hold 0 for none or k for m_shaders[k - 1], and are
    /// empty until a vertex (a triangle) has one.
    std::vector<Ref<SharedObject>> m_shaders;
    std::vector<std::uint32_t> m_vertexShaders;
    std::vector<std::uint32_t> m_triangleShaders;

    std::uint32_t shaderNumber(const SharedObject* shader);
    void setLastTriangleShader(std::uint32_t number);
};

/// Receives a geometry's decomposition. `own` is the geometry's own attribute
/// set (or null): what its vertices lack comes from it, then from the view.
class PrimitiveSink {
public:
    virtual ~PrimitiveSink() = default;
    virtual void draw(const MeshView& mesh, const AttributeSet* own) = 0;
};

} // namespace q3
