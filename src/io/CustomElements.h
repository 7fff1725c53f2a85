// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Apple's name and URL elements (QD3DCustomElements.h): two element classes
// Q3 registers itself (core/CustomClass.h), and their 3DMF forms, which are
// the only custom elements files carry:
//
//   Container ( Apple Computer, Inc.:NameElement ( ) CString ( "name" ) )
//   Apple Computer, Inc.:URLElement ( "url" options )   [ + CString ( "description" ) in a container ]
//
// as Quesa writes them and its test models hold them (binary files declare
// the class names with Type objects). They stand among a container's
// subobjects, a BeginGroup's, or an attribute set's.

#include "QD3DCustomElements.h"
#include "core/CustomClass.h"
#include "core/Object.h"

#include <memory>
#include <vector>

namespace q3 {
class Set;
}

namespace q3::io {

class ReadContext;
class WriteContext;
struct Node;

/// Registers the two classes unless they are (Q3Initialize calls it; the
/// calls below register too, so a class unregistered by the application
/// comes back when used).
void registerCustomElements();
std::shared_ptr<CustomClass> nameElementClass();
std::shared_ptr<CustomClass> urlElementClass();

/// The internal form of the URL element.
struct UrlElementData {
    char* url;
    char* description; ///< may be null
    std::uint32_t options;
};

/// Whether a subobject node is an element of a custom element class (a
/// name or URL element, or an application's element: its read-data method
/// reads it, io/CustomIO.h); the elements read are added to `made`. An
/// application's element class without a read-data method posts
/// kQ3WarningNoObjectSupportForReadMethod and gives false. Throws
/// kQ3ErrorInvalidMetafileObject for a malformed one.
bool readCustomElement(ReadContext& context, const Node& node, std::vector<std::unique_ptr<CustomElement>>& made);
/// Writes every custom element of the set: the name and URL elements, and
/// the elements of application classes with a traverse method (their
/// traverse and write methods write them); any other custom element posts
/// kQ3WarningNoObjectSupportForWriteMethod and is left out.
void writeCustomElements(WriteContext& context, const Set& set);
/// Whether writeCustomElements would write something.
bool hasFileElements(const Set* set);

} // namespace q3::io
