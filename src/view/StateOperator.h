// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Object.h"

namespace q3 {

extern const ClassInfo kStateOperatorClass;
extern const ClassInfo kPushClass;
extern const ClassInfo kPopClass;

/// Q3Push_New / Q3Pop_New: a shape that, submitted to a view (or met in a
/// group), does what Q3Push_Submit or Q3Pop_Submit does. It holds no data.
class StateOperator final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeStateOperator;

    explicit StateOperator(bool push) : m_push(push) {}

    const ClassInfo& classInfo() const override;
    Object* duplicate() const override;
    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor& visitor) const override;

    bool isPush() const { return m_push; }

private:
    bool m_push;
};

} // namespace q3
