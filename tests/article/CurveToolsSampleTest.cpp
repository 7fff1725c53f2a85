// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The curve_tools sample (samples/curve_tools): its figures, made with the curve
// tools, checked by numbers and against golden images; and the program itself,
// run as a user runs it.

#include "Golden.h"
#include "Q3ApiTest.h"

#include "Q3NURBCurveTools.h"
#include "figures.h"
#include "tool_figures.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

class CurveToolsSample : public q3test::Q3ApiTest {};

q3test::RgbaImage render(const Q3Figure& figure)
{
    q3test::RgbaImage image(Q3FIG_WIDTH, Q3FIG_HEIGHT);
    EXPECT_EQ(q3fig_render(&figure, Q3FIG_WIDTH, Q3FIG_HEIGHT, image.pixels.data()), 0);
    return image;
}

TEST_F(CurveToolsSample, Figure22ByTheKnotInsertionCallIsTheArticlesFigure)
{
    Q3Figure rebuilt;
    Q3Figure article;
    ASSERT_EQ(q3tools_figure22(&rebuilt), 0);
    ASSERT_EQ(q3fig_find(22, &article), 0);
    const Q3FigCurve& mine = rebuilt.curves[1];
    const Q3FigCurve& listing2 = article.curves[1];
    ASSERT_EQ(mine.numPoints, 6u);
    ASSERT_EQ(mine.numPoints, listing2.numPoints);
    for (unsigned long i = 0; i < mine.numPoints + mine.order; ++i)
        EXPECT_EQ(mine.knots[i], listing2.knots[i]) << i;
    // Both compute the article's alphas in double; the points agree to the last
    // float bit or one step of it.
    for (unsigned long i = 0; i < mine.numPoints; ++i) {
        EXPECT_NEAR(mine.points[i].x, listing2.points[i].x, 1e-6f) << i;
        EXPECT_NEAR(mine.points[i].y, listing2.points[i].y, 1e-6f) << i;
        EXPECT_EQ(mine.points[i].w, 1.0f) << i;
    }
    // B2 and B3 move onto the old control polygon (the article's Figure 22).
    EXPECT_NEAR(mine.points[2].x, 0.2f * 1.5f + 0.8f * 3.0f, 1e-6f);
    EXPECT_NEAR(mine.points[3].x, 0.7f * 3.0f + 0.3f * 4.5f, 1e-6f);
    EXPECT_TRUE(q3test::matchesGolden("figure22", render(rebuilt)));
}

TEST_F(CurveToolsSample, TheInterpolatingCurvesPassThroughThePoints)
{
    Q3Figure figure;
    ASSERT_EQ(q3tools_interpolation(&figure), 0);
    ASSERT_EQ(figure.numCurves, 4u);
    const TQ3Point3D* points = q3tools_interpolated_points();
    for (unsigned long c = 1; c < 4; ++c) {
        Q3FigCurve curve = figure.curves[c];
        const TQ3NURBCurveData data = q3fig_curve_data(&curve);
        const bool interpolates = c >= 2;
        EXPECT_EQ(data.numPoints, interpolates ? unsigned(Q3TOOLS_INTERPOLATED_POINTS) : 5u);
        for (int i = 0; i < Q3TOOLS_INTERPOLATED_POINTS; ++i) {
            float t = 0;
            TQ3Point3D closest;
            ASSERT_EQ(Q3NURBCurveData_GetClosestPoint(&data, &points[i], &t, &closest), kQ3Success);
            const double gap = std::hypot(closest.x - points[i].x, closest.y - points[i].y);
            const bool end = i == 0 || i == Q3TOOLS_INTERPOLATED_POINTS - 1;
            if (interpolates || end)
                EXPECT_LE(gap, 1e-5) << "curve " << c << " point " << i;
            else
                EXPECT_LE(gap, 1.0) << "the least-squares cubic stays near point " << i;
        }
    }
    EXPECT_TRUE(q3test::matchesGolden("curve_tools_interpolation", render(figure)));
}

TEST(CurveToolsSampleProgram, WritesBothFiguresAsTheTestsDrawThem)
{
    namespace fs = std::filesystem;
    const fs::path out = fs::path(Q3_TEST_SCRATCH_DIR) / "curve_tools";
    fs::remove_all(out);
    fs::create_directories(out.parent_path());
    const std::string command = std::string("\"") + Q3_CURVE_TOOLS_SAMPLE + "\" \"" + out.string() + "\" > \"" +
                                (out.parent_path() / "curve_tools.log").string() + "\"";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    q3test::RgbaImage figure22;
    q3test::RgbaImage interpolation;
    ASSERT_TRUE(q3test::readPng((out / "figure22_insert_knot.png").string(), &figure22));
    ASSERT_TRUE(q3test::readPng((out / "interpolation.png").string(), &interpolation));
    EXPECT_TRUE(q3test::matchesGolden("figure22", figure22));
    EXPECT_TRUE(q3test::matchesGolden("curve_tools_interpolation", interpolation));
}

} // namespace
