// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "style/Style.h"

#include "core/ShapeVisitor.h"

namespace q3 {

const ClassInfo kStyleClass{kQ3ShapeTypeStyle, &kShapeClass, "style"};

void Style::accept(ShapeVisitor& visitor) const
{
    visitor.visitStyle(*this);
}

} // namespace q3
