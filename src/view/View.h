// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DView.h"
#include "core/Object.h"
#include "core/ShapeVisitor.h"

namespace q3 {

extern const ClassInfo kViewClass;

/// A QuickDraw 3D view: draw context, camera, renderer, and the state stack
/// of a rendering or bounding loop. Not shared: disposing it destroys it.
class View final : public Object {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ObjectTypeView;

    View();
    ~View() override;

    const ClassInfo& classInfo() const override { return kViewClass; }

    /// Where shapes go when submitted: the active rendering or bounding pass.
    /// Throws kQ3ErrorViewNotStarted outside a loop.
    ShapeVisitor& submitTarget();
};

} // namespace q3
