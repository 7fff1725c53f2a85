// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3's side of the outside comparison (issue 30, item 8): the whole public
// path a program runs to get a curve's vertices, in a process of its own.
// The rational cubic of BenchCurves.h is made once as a retained NURB curve;
// inside a rendering loop under the constant subdivision style at 64
// segments per span, the program then times kOutsideCalls rounds of exactly
//   Q3Geometry_GetDecomposed -> Q3PolyLine_GetData -> Q3PolyLine_EmptyData
//   -> Q3Object_Dispose
// and prints one line (OutsideTiming.h). The vertices are counted, not read:
// the peer (GluCountOutside.cpp) only counts them too. Every call's count is
// checked against spans * 64 + 1. outside.py runs both programs in turns.

#include "BenchCurves.h"
#include "BenchView.h"
#include "OutsideTiming.h"

#include <cstdio>

int main()
{
    const q3bench::BenchCurve curve = q3bench::rationalCubic();
    const std::uint64_t expected = curve.spanCount() * q3bench::kSegmentsPerSpan + 1;
    q3bench::Q3Session session;
    q3bench::BenchView view(64, 64);
    const TQ3NURBCurveData data = q3bench::curveData(curve);
    TQ3GeometryObject nurb = Q3NURBCurve_New(&data);
    if (nurb == nullptr || Q3View_StartRendering(view.view()) != kQ3Success) {
        std::fprintf(stderr, "q3: creating the curve or starting the rendering loop failed\n");
        return 1;
    }
    const TQ3SubdivisionStyleData style = q3bench::constantStyle(float(q3bench::kSegmentsPerSpan));
    Q3SubdivisionStyle_Submit(&style, view.view());

    std::uint64_t delivered = 0;
    int failures = 0;
    q3bench::CallTimes times;
    const q3bench::ProcessClock clock;
    for (int call = 0; call < q3bench::kOutsideCalls; ++call) {
        times.start();
        TQ3GeometryObject decomposed = Q3Geometry_GetDecomposed(nurb, view.view());
        TQ3PolyLineData polyLine{};
        if (decomposed != nullptr && Q3PolyLine_GetData(decomposed, &polyLine) == kQ3Success) {
            delivered += polyLine.numVertices;
            Q3PolyLine_EmptyData(&polyLine);
        } else {
            ++failures;
        }
        if (decomposed != nullptr)
            Q3Object_Dispose(decomposed);
        times.stop();
    }
    const q3bench::ProcessClock::Elapsed elapsed = clock.elapsed();

    Q3View_EndRendering(view.view());
    Q3Object_Dispose(nurb);
    if (failures != 0 || delivered != expected * q3bench::kOutsideCalls) {
        std::fprintf(stderr, "q3: %d calls failed; %llu vertices delivered, %llu expected\n", failures,
                     static_cast<unsigned long long>(delivered),
                     static_cast<unsigned long long>(expected * q3bench::kOutsideCalls));
        return 1;
    }
    q3bench::printOutsideResult("q3", q3bench::kOutsideCalls, expected, elapsed, times);
    return 0;
}
