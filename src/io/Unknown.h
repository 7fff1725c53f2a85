// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3D.h"
#include "core/Object.h"

#include <cstdint>
#include <map>
#include <string>

namespace q3 {

extern const ClassInfo kUnknownClass;
extern const ClassInfo kUnknownTextClass;
extern const ClassInfo kUnknownBinaryClass;

/// An object of a type Q3 does not know, read from a file and kept so that
/// it is written back unchanged (QD3DIO.h). Drawing it does nothing.
/// Invariant: its contents never change after it is read.
class UnknownObject : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3ShapeTypeUnknown;

    bool isDrawable() const override { return true; }
    void accept(ShapeVisitor&) const override {}

    bool dirty() const { return m_dirty; }
    void setDirty(bool dirty) { m_dirty = dirty; }

private:
    bool m_dirty = false;
};

/// From a text file: the object's name and the text between its parentheses.
class UnknownText final : public UnknownObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3UnknownTypeText;

    UnknownText(std::string name, std::string contents) : m_name(std::move(name)), m_contents(std::move(contents)) {}

    const ClassInfo& classInfo() const override { return kUnknownTextClass; }
    Object* duplicate() const override;

    const std::string& name() const { return m_name; }
    const std::string& contents() const { return m_contents; }

private:
    std::string m_name;
    std::string m_contents;
};

/// From a binary file: the type, the data as they were, and the file's byte
/// order.
class UnknownBinary final : public UnknownObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3UnknownTypeBinary;

    UnknownBinary(TQ3ObjectType type, std::string contents, TQ3Endian order, std::string typeString = {})
        : m_type(type), m_contents(std::move(contents)), m_order(order), m_typeString(std::move(typeString))
    {
    }

    const ClassInfo& classInfo() const override { return kUnknownBinaryClass; }
    Object* duplicate() const override;

    TQ3ObjectType type() const { return m_type; }
    const std::string& contents() const { return m_contents; }
    TQ3Endian byteOrder() const { return m_order; }
    /// The class name a Type object of the file declared for a custom
    /// (negative) type; empty for any other type.
    const std::string& typeString() const { return m_typeString; }
    /// The custom types the data's objects have (a container's, a group's),
    /// by their codes in the data: the names their file's Type objects gave.
    const std::map<std::uint32_t, std::string>& declaredTypes() const { return m_declared; }
    void setDeclaredTypes(std::map<std::uint32_t, std::string> declared) { m_declared = std::move(declared); }

private:
    TQ3ObjectType m_type;
    std::string m_contents;
    TQ3Endian m_order;
    std::string m_typeString;
    std::map<std::uint32_t, std::string> m_declared;
};

} // namespace q3
