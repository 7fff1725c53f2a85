// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "core/Object.h"

#include <string>

namespace q3 {

extern const ClassInfo kStringClass;
extern const ClassInfo kCStringClass;

/// A C string object (QD3DString.h, kQ3StringTypeCString): what
/// Q3File_GetExternalReferences returns, one per external reference.
/// Invariant: m_text holds no NUL character.
class CString final : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3StringTypeCString;

    explicit CString(std::string text) : m_text(std::move(text)) {}
    const ClassInfo& classInfo() const override { return kCStringClass; }
    Object* duplicate() const override { return makeShared<CString>(m_text).detach(); }

    const std::string& text() const { return m_text; }
    void setText(std::string text) { m_text = std::move(text); }

private:
    std::string m_text;
};

} // namespace q3
