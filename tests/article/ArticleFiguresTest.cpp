// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Every figure article_figures draws, rendered through the same q3figures
// code at the same size and compared with tests/golden/figureNN.png.

#include "Golden.h"
#include "Q3ApiTest.h"

#include "figures.h"

#include <string>

namespace {

class FigureGolden : public q3test::Q3ApiTest, public ::testing::WithParamInterface<unsigned long> {};

TEST_P(FigureGolden, MatchesTheGolden)
{
    Q3Figure figure;
    ASSERT_EQ(q3fig_build(GetParam(), &figure), 0);
    q3test::RgbaImage image(Q3FIG_WIDTH, Q3FIG_HEIGHT);
    ASSERT_EQ(q3fig_render(&figure, Q3FIG_WIDTH, Q3FIG_HEIGHT, image.pixels.data()), 0);
    EXPECT_TRUE(q3test::matchesGolden(figure.name, image));
}

std::string figureName(const ::testing::TestParamInfo<unsigned long>& info)
{
    Q3Figure figure;
    return q3fig_build(info.param, &figure) == 0 ? std::string(figure.name)
                                                 : "index" + std::to_string(info.param);
}

INSTANTIATE_TEST_SUITE_P(Article, FigureGolden, ::testing::Range(0ul, q3fig_count()), figureName);

} // namespace
