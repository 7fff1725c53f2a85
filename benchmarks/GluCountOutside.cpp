// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// GLU's side of the outside comparison (issue 30, item 8), in a process of
// its own that holds nothing of Q3: kOutsideCalls gluNurbsCurve calls on the
// rational cubic of BenchCurves.h in GLU_NURBS_TESSELLATOR mode, sampled with
// GLU_DOMAIN_DISTANCE at GLU_U_STEP = 63.5 / knot spacing (64 segments per
// span, as GluTessellateBench.cpp sets it), timed as one loop, one line
// printed (OutsideTiming.h). The peer does the least work it can: its vertex
// callback only counts (no division by w, no store). GLU makes each span a
// line strip of its own, so it delivers 65 vertices per span (the joints
// twice) where Q3's polyline has spans * 64 + 1; every call's count is
// checked.

#include "BenchCurves.h"
#include "OutsideTiming.h"

#include <GL/glu.h>

#include <cstdio>

namespace {

std::uint64_t g_vertices = 0;
GLenum g_error = 0;

void GLAPIENTRY onVertex(GLfloat*)
{
    ++g_vertices;
}

void GLAPIENTRY onError(GLenum error)
{
    g_error = error;
}

using Callback = void(GLAPIENTRY*)();

} // namespace

int main()
{
    const q3bench::BenchCurve curve = q3bench::rationalCubic();
    const std::uint64_t expected = curve.spanCount() * (q3bench::kSegmentsPerSpan + 1);
    GLUnurbs* nurbs = gluNewNurbsRenderer();
    gluNurbsProperty(nurbs, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(nurbs, GLU_AUTO_LOAD_MATRIX, GL_FALSE);
    gluNurbsCallback(nurbs, GLU_NURBS_VERTEX, reinterpret_cast<Callback>(onVertex));
    gluNurbsCallback(nurbs, GLU_NURBS_ERROR, reinterpret_cast<Callback>(onError));
    gluNurbsProperty(nurbs, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nurbs, GLU_U_STEP, float((q3bench::kSegmentsPerSpan - 0.5) / q3bench::kKnotSpacing));

    q3bench::CallTimes times;
    const q3bench::ProcessClock clock;
    for (int call = 0; call < q3bench::kOutsideCalls; ++call) {
        times.start();
        gluBeginCurve(nurbs);
        gluNurbsCurve(nurbs, GLint(curve.knots.size()), const_cast<float*>(curve.knots.data()), 4,
                      const_cast<float*>(curve.points.data()), GLint(curve.order), GL_MAP1_VERTEX_4);
        gluEndCurve(nurbs);
        times.stop();
    }
    const q3bench::ProcessClock::Elapsed elapsed = clock.elapsed();
    gluDeleteNurbsRenderer(nurbs);

    if (g_error != 0 || g_vertices != expected * q3bench::kOutsideCalls) {
        std::fprintf(stderr, "glu: error %u; %llu vertices delivered, %llu expected\n", unsigned(g_error),
                     static_cast<unsigned long long>(g_vertices),
                     static_cast<unsigned long long>(expected * q3bench::kOutsideCalls));
        return 1;
    }
    q3bench::printOutsideResult("glu", q3bench::kOutsideCalls, expected, elapsed, times);
    return 0;
}
