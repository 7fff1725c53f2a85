// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include <string>
#include <utility>

namespace q3 {

/// Why a render/ call failed. The render layer neither throws nor posts to the
/// error manager: it returns one of these and the view layer decides which
/// QuickDraw 3D error (if any) it becomes.
enum class RenderStatus {
    kOk,
    kInvalidArgument,   ///< a parameter is out of range, NULL, NaN or infinite
    kWrongState,        ///< draw outside a frame, beginFrame twice, ...
    kOutOfMemory,       ///< a CPU-side buffer could not grow
    kContextFailure,    ///< no backend, or it refused to create or bind a context
    kWrongRenderer,     ///< the GL implementation is not the pinned one (llvmpipe)
    kGraphicsError,     ///< the GL reported an error while drawing
};

/// A status plus a human-readable message (empty on success). Cheap to return
/// on success: the empty message does not allocate.
struct RenderResult {
    RenderStatus status = RenderStatus::kOk;
    std::string message;

    bool ok() const noexcept { return status == RenderStatus::kOk; }
    explicit operator bool() const noexcept { return ok(); }

    static RenderResult success() { return {}; }
    static RenderResult failure(RenderStatus status, std::string message)
    {
        return {status, std::move(message)};
    }
};

/// A rectangle of pixels. y is measured from the top row downwards, as
/// QuickDraw 3D panes and pixmaps are; width and height are in pixels.
struct PixelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
};

} // namespace q3
