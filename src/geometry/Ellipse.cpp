// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Ellipse.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kEllipseClass{kQ3GeometryTypeEllipse, &kGeometryClass, "ellipse"};

template class DataGeometry<Ellipse, TQ3EllipseData>;

void Ellipse::check(const TQ3EllipseData& d)
{
    checkEllipseData(d);
}

std::string Ellipse::degeneracy(const TQ3EllipseData& d)
{
    return firstCase({dependentFrame(d.majorRadius, d.minorRadius, "majorRadius and minorRadius"),
                      emptyAngle(d.uMin, d.uMax, "uMin", "uMax")});
}

void Ellipse::decompose(const DecomposeContext& context, PrimitiveSink& sink) const
{
    if (!emptyAngle(data().uMin, data().uMax, "uMin", "uMax").empty())
        return;
    const SubdivisionMeasure measure = context.subdivisionMeasure();
    std::string report;
    withMesh(
        measure.key(),
        [&](Mesh& mesh) {
            const TQ3EllipseData& d = data();
            const quadric::EllipseShape shape{toVec3(d.origin), toVec3(d.majorRadius), toVec3(d.minorRadius),
                                              quadric::angularRange(d.uMin, d.uMax)};
            const quadric::Polyline line = quadric::tessellateCurve(
                [&](double u) { return quadric::ellipsePoint(shape, u); }, shape.u.min, shape.u.max, shape.u.full(),
                subdivisionFor(measure, 0), limits::kMaxSegmentsPerCurve);
            for (const quadric::Vec3& p : line.points)
                mesh.addVertex(TQ3Point3D{float(p.x), float(p.y), float(p.z)}, VertexAttributes{});
            mesh.addStrip(0, std::uint32_t(line.points.size()));
            m_report.clear();
            if (line.reduced) {
                SubdivisionShortfall shortfall;
                shortfall.shape = "an ellipse";
                shortfall.limit = "kQ3SubdivisionMaxSegmentsPerCurve (" +
                                  std::to_string(limits::kMaxSegmentsPerCurve) + ") segments";
                shortfall.used = measure.method == kQ3SubdivisionMethodConstant
                                     ? "fewer are used"
                                     : "segments up to " + std::to_string(line.effective) + " long are used";
                m_report = subdivisionWarning(measure, shortfall);
            }
        },
        [&](const Mesh& mesh) {
            report = m_report;
            sink.draw(mesh.view(), attributeSet());
        });
    if (!report.empty())
        errors::postWarning(kQ3WarningParameterOutOfRange, report);
}

void Ellipse::bound(const DecomposeContext&, std::vector<glm::dvec3>& points) const
{
    if (!emptyAngle(data().uMin, data().uMax, "uMin", "uMax").empty())
        return;
    ellipseBoxCorners(toVec3(data().origin), toVec3(data().majorRadius), toVec3(data().minorRadius), points);
}

} // namespace q3
