// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "base/Primitives.h"
#include "view/Pass.h"
#include "view/Pick.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace q3 {

/// A traversal of a picking loop: every geometry decomposes itself into this
/// pass (as for drawing), which tests the points, segments, strips and
/// triangles against the pick (view/PickMath.h) and keeps, per geometry
/// submission, the nearest hit of each kind the pick parts style asks for
/// (the whole object; or its face, edge and vertex). Screen-space bitmaps
/// and pixmaps (markers) count as faces covering their rectangles.
///
/// Window picks work in the pane's pixels: triangles by the world ray
/// through the window point (from the hither to the yon plane), points and
/// lines by their distance in pixels after clipping to the depth range;
/// window-rect picks by overlap of the clipped, projected primitives with
/// the rectangle. World-ray picks work in world units.
/// Invariant: the path holds one entry per display group being traversed,
/// each with the position of the object it is submitting.
class PickPass final : public Pass, private PrimitiveSink {
public:
    /// window: the loop's camera and pane (required for window picks).
    PickPass(const Pick& pick, std::optional<Window> window, const AttributeValues& attributes);

    void visitGeometry(const Geometry& geometry) override;
    bool beginGroup(const DisplayGroup& group) override;
    void endGroup(const DisplayGroup& group) override;
    void atGroupPosition(OpaqueTQ3GroupPosition* position) override;
    /// What a custom object's submit method submits is picked as that
    /// object: its hits (the nearest of each kind over everything it
    /// submitted) name it, with the path to it, its pick ID and its
    /// local-to-world; no shape part (QD3DPick.h's shape parts are a
    /// mesh's). Custom objects a submit method submits are part of the
    /// outermost one.
    void beginCustomObject(const Object& object) override;
    void endCustomObject(const Object& object, bool submitted) override;

    /// The hits found so far, in submission order.
    std::vector<PickHit>& hits() { return m_hits; }

private:
    /// The best hit of one kind for the geometry being tested.
    struct Candidate {
        bool found = false;
        double distance = 0.0;
        glm::dvec3 xyz{0.0};
        std::optional<glm::dvec3> normal;
        std::optional<glm::dvec2> uv;
    };
    enum Slot { kObject, kFace, kEdge, kVertex, kSlots };

    void draw(const MeshView& mesh, const AttributeSet* own) override;
    /// Offers a hit of `slot` (and of the whole object).
    void offer(Slot slot, const Candidate& candidate);

    void testTriangles(const MeshView& mesh);
    void testSegment(const MeshView& mesh, std::uint32_t a, std::uint32_t b);
    void testVertex(const MeshView& mesh, std::uint32_t v);
    void testScreenRect(const MeshView& mesh, std::uint32_t anchor, long xOffset, long yOffset,
                        std::uint32_t width, std::uint32_t height);
    bool wants(Slot slot) const;
    /// What the hits of one submission name.
    struct Source {
        const SharedObject* object; ///< the hit's object (null: none, immediate mode)
        const Geometry* parts;      ///< asked for shape parts (null: none)
        TQ3PickParts pickParts;
        unsigned long pickID;
        Matrix localToWorld;
    };
    /// Adds the hits `best` holds for one submission, with the current path.
    void addHits(const Candidate (&best)[kSlots], const Source& source);

    glm::dvec3 world(const MeshView& mesh, std::uint32_t v) const;
    glm::dvec4 clip(const MeshView& mesh, std::uint32_t v) const;
    glm::dvec2 toPane(const glm::dvec4& clip) const;

    Pick::Kind m_kind;
    TQ3PickData m_data;
    glm::dvec2 m_point{0.0};
    glm::dvec2 m_rectMin{0.0};
    glm::dvec2 m_rectMax{0.0};
    double m_vertexTolerance = 0.0;
    double m_edgeTolerance = 0.0;
    /// The ray (world-ray picks; window-point picks: through the point from
    /// the hither plane), direction of unit length, and how far it may go.
    glm::dvec3 m_origin{0.0};
    glm::dvec3 m_direction{0.0, 0.0, -1.0};
    double m_reach = 0.0;
    bool m_rayValid = false;

    /// For the mesh being tested: local-to-world and local-to-frustum.
    Matrix m_toWorld{1.0};
    Matrix m_toClip{1.0};
    Candidate m_best[kSlots];

    struct Level {
        const DisplayGroup* group;
        OpaqueTQ3GroupPosition* position;
    };
    std::vector<Level> m_path;
    /// The outermost custom object being submitted, and how deep its
    /// submit methods nest.
    struct Custom {
        const Object* object = nullptr;
        std::size_t depth = 0;
        Candidate best[kSlots];
        TQ3PickParts pickParts = kQ3PickPartsObject;
        unsigned long pickID = 0;
        Matrix localToWorld{1.0};
    };
    Custom m_custom;
    std::vector<PickHit> m_hits;
    std::vector<glm::dvec4> m_polygon;
};

} // namespace q3
