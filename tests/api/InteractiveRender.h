// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Drawing with the interactive renderer into a new pixmap of a fixed size,
// as the texture render tests do: their fixtures derive from
// InteractiveRendering<width, height>.

#include "RenderTestSupport.h"

#include "QD3DShader.h"

#include <functional>

namespace q3test {

template <int Width, int Height>
struct InteractiveRendering {
    /// A Width x Height interactive rendering whose every pass calls `submit`.
    static Pixmap render(const std::function<void(TQ3ViewObject)>& submit)
    {
        Pixmap image(Width, Height);
        TestView view(image.pixmap(), kQ3RendererTypeInteractive);
        EXPECT_EQ(view.render(submit), kQ3ViewStatusDone);
        return image;
    }

    /// The same, drawing `geometry` with `shader` submitted to the view
    /// before it.
    static Pixmap renderUnder(TQ3ShaderObject shader, TQ3GeometryObject geometry)
    {
        return render([&](TQ3ViewObject v) {
            Q3Shader_Submit(shader, v);
            Q3Geometry_Submit(geometry, v);
        });
    }
};

} // namespace q3test
