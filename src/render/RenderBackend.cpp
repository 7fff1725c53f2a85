// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "base/RenderTarget.h"
#include "render/OffscreenRenderer.h"

// The backends this library draws with: OffscreenRenderer over OSMesa or EGL,
// chosen per view by Q3_RENDER_BACKEND (GlContext.h). The view asks
// base/RenderTarget.h for a target and never names it.

namespace q3 {

std::unique_ptr<RenderTarget> makeRenderTarget()
{
    return std::make_unique<OffscreenRenderer>();
}

void initializeRenderBackend()
{
    pinRenderingEnvironment();
}

} // namespace q3
