// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/StateOperator.h"

#include "core/ShapeVisitor.h"

namespace q3 {

const ClassInfo kStateOperatorClass{kQ3ShapeTypeStateOperator, &kShapeClass, "state operator"};
const ClassInfo kPushClass{kQ3StateOperatorTypePush, &kStateOperatorClass, "push"};
const ClassInfo kPopClass{kQ3StateOperatorTypePop, &kStateOperatorClass, "pop"};

const ClassInfo& StateOperator::classInfo() const
{
    return m_push ? kPushClass : kPopClass;
}

Object* StateOperator::duplicate() const
{
    return makeShared<StateOperator>(m_push).detach();
}

void StateOperator::accept(ShapeVisitor& visitor) const
{
    if (m_push)
        visitor.pushState();
    else
        visitor.popState();
}

} // namespace q3
