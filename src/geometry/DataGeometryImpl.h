// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The members of DataGeometry, included only by the .cpp of a geometry class,
// which instantiates them next to its data description. TQ3Vertex3D, part of
// many descriptions, is described here once.

#include "core/DataLayout.h"
#include "core/ErrorManager.h"
#include "geometry/DataGeometry.h"

#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

namespace q3 {
namespace layout {

template <>
struct Describe<TQ3Vertex3D> {
    static auto fields()
    {
        return std::make_tuple(finite("point", &TQ3Vertex3D::point),
                               handle<AttributeSet>("attributeSet", &TQ3Vertex3D::attributeSet));
    }
};

} // namespace layout

/// Specialized as true, in its .cpp before the explicit instantiation, for a
/// class whose check() covers its structure itself in an order its header
/// documents (the NURB curve and patch: orders and counts before the arrays'
/// presence). Its description's structural check then runs after check().
template <class Derived>
struct ChecksItsOwnStructure : std::false_type {};

namespace detail {
template <class T, class D, class = void>
struct HasDegeneracy : std::false_type {};
template <class T, class D>
struct HasDegeneracy<T, D, std::void_t<decltype(T::degeneracy(std::declval<const D&>()))>> : std::true_type {};
} // namespace detail

template <class Derived, class Data>
void DataGeometry<Derived, Data>::validate(const Data* data)
{
    requireNonNull(data, Derived::kDataName);
    checkData(*data);
    warnIfDegenerate(*data);
}

template <class Derived, class Data>
void DataGeometry<Derived, Data>::checkData(const Data& data)
{
    if constexpr (ChecksItsOwnStructure<Derived>::value) {
        Derived::check(data);
        layout::checkStructure(data, layout::Path{});
    } else {
        layout::checkStructure(data, layout::Path{});
        Derived::check(data);
    }
}

template <class Derived, class Data>
void DataGeometry<Derived, Data>::warnIfDegenerate(const Data& data)
{
    if constexpr (detail::HasDegeneracy<Derived, Data>::value) {
        const std::string problem = Derived::degeneracy(data);
        if (problem.empty())
            return;
        layout::checkHandles(data, layout::Path{});
        errors::postWarning(kQ3WarningInconsistentData, std::string("the ") + Derived::kName + " is degenerate (" +
                                                            problem + "); it is kept as given");
    } else {
        (void)data;
    }
}

template <class Derived, class Data>
DataGeometry<Derived, Data>::DataGeometry(const Data& data)
{
    layout::copyData(m_data, data, layout::RetainChecked{});
}

template <class Derived, class Data>
DataGeometry<Derived, Data>::DataGeometry(BorrowData, const Data& data) : m_borrowed(true)
{
    layout::checkHandles(data, layout::Path{});
    std::memcpy(static_cast<void*>(&m_data), &data, sizeof(Data));
    disableCaching();
}

template <class Derived, class Data>
DataGeometry<Derived, Data>::DataGeometry(DuplicateData, const Data& source)
{
    layout::copyData(m_data, source, layout::DuplicateEach{});
}

template <class Derived, class Data>
DataGeometry<Derived, Data>::DataGeometry(AdoptData, Data& owned)
{
    std::memcpy(static_cast<void*>(&m_data), &owned, sizeof(Data));
    layout::clearOwned(owned);
}

template <class Derived, class Data>
DataGeometry<Derived, Data>::~DataGeometry()
{
    if (!m_borrowed)
        layout::release(m_data);
}

template <class Derived, class Data>
void DataGeometry<Derived, Data>::getData(Data& out) const
{
    layout::copyData(out, m_data, layout::RetainTrusted{});
}

template <class Derived, class Data>
void DataGeometry<Derived, Data>::setData(const Data& data)
{
    validate(&data);
    Data fresh;
    layout::copyData(fresh, data, layout::RetainChecked{});
    std::swap(m_data, fresh);
    layout::release(fresh);
    markEdited();
}

template <class Derived, class Data>
void DataGeometry<Derived, Data>::emptyData(Data& data)
{
    layout::emptyData(data);
}

template <class Derived, class Data>
Object* DataGeometry<Derived, Data>::duplicate() const
{
    Ref<Derived> copy = Ref<Derived>::adopt(new Derived(DuplicateData{}, m_data));
    copy->registerLive();
    return copy.detach();
}

template <class Derived, class Data>
const AttributeSet* DataGeometry<Derived, Data>::attributeSet() const
{
    return heldAttributeSet(m_data.*Derived::kOwnSet);
}

template <class Derived, class Data>
void DataGeometry<Derived, Data>::setAttributeSet(Ref<AttributeSet> attributes)
{
    replaceHeldSet(m_data.*Derived::kOwnSet, std::move(attributes));
    markEdited();
}

} // namespace q3
