// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/Unknown.h"

namespace q3 {

const ClassInfo kUnknownClass{kQ3ShapeTypeUnknown, &kShapeClass, "unknown object"};
const ClassInfo kUnknownTextClass{kQ3UnknownTypeText, &kUnknownClass, "unknown text object"};
const ClassInfo kUnknownBinaryClass{kQ3UnknownTypeBinary, &kUnknownClass, "unknown binary object"};

Object* UnknownText::duplicate() const
{
    return makeShared<UnknownText>(m_name, m_contents).detach();
}

Object* UnknownBinary::duplicate() const
{
    auto copy = makeShared<UnknownBinary>(m_type, m_contents, m_order, m_typeString);
    copy->setDeclaredTypes(m_declared);
    return copy.detach();
}

} // namespace q3
