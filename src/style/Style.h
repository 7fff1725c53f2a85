// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Object.h"
#include "base/DrawState.h"

namespace q3 {

extern const ClassInfo kStyleClass;

/// Every QuickDraw 3D style: a drawable shared object that, submitted to a
/// view, sets one part of the traversal's DrawState. Invariant: apply()
/// changes only the style's own field of the state.
class Style : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeStyle;

    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    /// Puts the style's value into the state.
    virtual void apply(DrawState& state) const = 0;

protected:
    Style() = default;
};

} // namespace q3
