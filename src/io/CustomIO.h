// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The 3DMF form of the classes applications register (QD3DIO.h's I/O
// methods): objects and elements are written by their class's traverse and
// write methods and read by its read or read-data method, under the class
// name (binary files declare it with a Type object, io/Metafile.h).
//
// Writing runs in two steps, as QuickDraw 3D's writer does: the traverse
// method runs with a CustomWrite collecting what it submits (its own data,
// subobjects, subobject data), then the object is written from that: its
// data by the write method, the subobjects after it in a Container.

#include "QD3DIO.h"
#include "core/CustomClass.h"
#include "core/Object.h"
#include "core/Ref.h"

#include <memory>
#include <optional>
#include <vector>

namespace q3::io {

class ReadContext;
class WriteContext;
struct Node;

/// What one traverse method submitted. Invariant: every data block given
/// with a delete method has it called exactly once, when this goes.
class CustomWrite {
public:
    CustomWrite(WriteContext& context, std::shared_ptr<CustomClass> customClass)
        : m_context(context), m_class(std::move(customClass))
    {
    }
    CustomWrite(const CustomWrite&) = delete;
    CustomWrite& operator=(const CustomWrite&) = delete;
    ~CustomWrite();

    TQ3ViewObject view() const;
    /// Q3XView_SubmitWriteData: throws kQ3ErrorWriteStateInactive when the
    /// data were submitted already, kQ3ErrorNeedRequiredMethods for data
    /// without a write method.
    void submitData(std::size_t size, void* data, TQ3XDataDeleteMethod deleteData);
    /// Q3XView_SubmitSubObjectData.
    void submitSubObjectData(std::shared_ptr<CustomClass> subClass, std::size_t size, void* data,
                             TQ3XDataDeleteMethod deleteData);
    /// A retained object submitted (written as WriteContext::object does).
    void submitObject(const Object& object);
    /// An immediate-mode object submitted (a copy is kept until written).
    void submitTemporary(const Object& object);
    /// Writes what was submitted (nothing when the method submitted no data).
    void write();

private:
    struct Data {
        std::shared_ptr<CustomClass> customClass;
        std::size_t size;
        void* data;
        TQ3XDataDeleteMethod deleteData;
    };
    struct Sub {
        std::optional<Data> data;
        Ref<SharedObject> object;
        bool temporary = false;
    };
    void requireData() const;
    void writeData(const Data& data);

    WriteContext& m_context;
    std::shared_ptr<CustomClass> m_class;
    std::optional<Data> m_own;
    std::vector<Sub> m_subs;
};

/// The class whose methods write the object (an object of a registered
/// class with a traverse method), or null.
const CustomClass* customWriterOf(const Object& object);
/// Writes an object customWriterOf() names a class for.
void writeCustomObject(WriteContext& context, const Object& object);
/// Writes an element through its class's traverse and write methods;
/// false when the class has no traverse method.
bool writeCustomElement(WriteContext& context, const CustomElement& element);
/// Whether writeCustomElement writes elements of the class.
bool writesCustomElements(const CustomClass& elementClass);

/// The writing loop's collector a traverse method running for `view` on
/// this thread submits to; throws kQ3ErrorWriteStateInactive when none is.
CustomWrite& activeCustomWrite(TQ3ViewObject view);

/// An object of a registered object class read by its read method; null
/// when the class has none or no file object reads (the caller reads it as
/// an unknown object, with kQ3WarningNoObjectSupportForReadMethod posted
/// here). Throws kQ3ErrorInvalidMetafileObject when the method fails.
Ref<SharedObject> readCustomObject(ReadContext& context, const Node& node, const CustomClass& objectClass);
/// Q3File_ReadObject of an element of a registered element or attribute
/// class (an application's, or Apple's name and URL elements): a new set
/// (kQ3SharedTypeSet) holding it, as QuickDraw 3D's and Quesa's readers
/// give it to a read method going through its container. Null when the
/// node is no such element (or its class has no read-data method, which
/// posts kQ3WarningNoObjectSupportForReadMethod: it is then an unknown
/// object).
Ref<SharedObject> readElementAsSet(ReadContext& context, const Node& node);
/// The elements the read-data method of an element class made from the
/// node; false (and nothing made) when the class has none
/// (kQ3WarningNoObjectSupportForReadMethod posted). Throws
/// kQ3ErrorInvalidMetafileObject when the method fails.
bool readCustomElementData(ReadContext& context, const Node& node, const CustomClass& elementClass,
                           std::vector<std::unique_ptr<CustomElement>>& made);

} // namespace q3::io
