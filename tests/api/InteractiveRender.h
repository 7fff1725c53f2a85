// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Drawing with the interactive renderer into a new pixmap, as the texture
// render tests do.

#include "RenderTestSupport.h"

#include "QD3DShader.h"

#include <functional>

namespace q3test {

/// A width x height interactive rendering whose every pass calls `submit`.
inline Pixmap renderInteractive(int width, int height, const std::function<void(TQ3ViewObject)>& submit)
{
    Pixmap image(width, height);
    TestView view(image.pixmap(), kQ3RendererTypeInteractive);
    EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
    return image;
}

/// The same, drawing `geometry` with `shader` submitted to the view before it.
inline Pixmap renderUnderShader(int width, int height, TQ3ShaderObject shader, TQ3GeometryObject geometry)
{
    return renderInteractive(width, height, [&](TQ3ViewObject v) {
        Q3Shader_Submit(shader, v);
        Q3Geometry_Submit(geometry, v);
    });
}

} // namespace q3test
