// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/CustomIO.h"

#include "core/AttributeSet.h"
#include "core/CustomObject.h"
#include "core/ErrorManager.h"
#include "io/ClassIO.h"
#include "io/CustomElements.h"
#include "io/File.h"

#include <algorithm>
#include <string>

namespace q3::io {
namespace {

struct Active {
    TQ3ViewObject view;
    CustomWrite* collector;
};

// The traverse methods running on this thread, innermost last.
thread_local std::vector<Active> t_active;

/// While a traverse method runs: submits go to `collector`, and
/// Q3XView_SubmitWriteData finds it from the view.
class Collecting {
public:
    Collecting(WriteContext& context, CustomWrite& collector)
        : m_context(context), m_previous(context.setCollecting(&collector))
    {
        t_active.push_back({context.view(), &collector});
        context.enterMethod();
    }
    ~Collecting()
    {
        m_context.leaveMethod();
        t_active.pop_back();
        m_context.setCollecting(m_previous);
    }
    Collecting(const Collecting&) = delete;
    Collecting& operator=(const Collecting&) = delete;

private:
    WriteContext& m_context;
    CustomWrite* m_previous;
};

template <class Traverse>
void runTraverse(WriteContext& context, CustomWrite& collector, const CustomClass& customClass, Traverse&& traverse)
{
    TQ3Status status;
    {
        Collecting scope(context, collector);
        status = traverse();
    }
    if (status != kQ3Success)
        fail(kQ3ErrorInvalidParameter, "the traverse method of the class \"" + customClass.name() + "\" failed");
}

std::shared_ptr<CustomClass> registered(const CustomClass& customClass)
{
    std::shared_ptr<CustomClass> found = findCustomClass(customClass.type());
    if (found.get() != &customClass)
        fail(kQ3ErrorInvalidObjectClass, "the class \"" + customClass.name() + "\" is no longer registered");
    return found;
}

TQ3XObjectTraverseMethod elementTraverse(const CustomClass& elementClass)
{
    if (auto traverseData = elementClass.methodAs<TQ3XObjectTraverseDataMethod>(kQ3XMethodTypeObjectTraverseData))
        return traverseData;
    return elementClass.methodAs<TQ3XObjectTraverseMethod>(kQ3XMethodTypeObjectTraverse);
}

File& readingFile(ReadContext& context)
{
    return *context.fileObject();
}

} // namespace

CustomWrite::~CustomWrite()
{
    if (m_own && m_own->deleteData != nullptr)
        m_own->deleteData(m_own->data);
    for (Sub& sub : m_subs)
        if (sub.data && sub.data->deleteData != nullptr)
            sub.data->deleteData(sub.data->data);
}

TQ3ViewObject CustomWrite::view() const
{
    return m_context.view();
}

void CustomWrite::submitData(std::size_t size, void* data, TQ3XDataDeleteMethod deleteData)
{
    if (m_own)
        fail(kQ3ErrorWriteStateInactive, "Q3XView_SubmitWriteData was called already for this object");
    if (size != 0 && m_class->method(kQ3XMethodTypeObjectWrite) == nullptr)
        fail(kQ3ErrorNeedRequiredMethods,
             "the class \"" + m_class->name() + "\" has no write method (kQ3XMethodTypeObjectWrite) to write its data");
    m_own = Data{m_class, size, data, deleteData};
}

void CustomWrite::requireData() const
{
    if (!m_own)
        fail(kQ3ErrorWriteStateInactive,
             "a traverse method submits its own data (Q3XView_SubmitWriteData) before any subobject");
}

void CustomWrite::submitSubObjectData(std::shared_ptr<CustomClass> subClass, std::size_t size, void* data,
                                      TQ3XDataDeleteMethod deleteData)
{
    requireData();
    if (size != 0 && subClass->method(kQ3XMethodTypeObjectWrite) == nullptr)
        fail(kQ3ErrorNeedRequiredMethods, "the class \"" + subClass->name() +
                                              "\" has no write method (kQ3XMethodTypeObjectWrite) to write its data");
    m_subs.push_back(Sub{Data{std::move(subClass), size, data, deleteData}, {}, false});
}

void CustomWrite::submitObject(const Object& object)
{
    requireData();
    auto& shared = const_cast<SharedObject&>(static_cast<const SharedObject&>(object));
    m_subs.push_back(Sub{std::nullopt, Ref<SharedObject>::retain(&shared), false});
}

void CustomWrite::submitTemporary(const Object& object)
{
    requireData();
    Object* copy = object.duplicate(); // registered, with its one reference
    m_subs.push_back(Sub{std::nullopt, Ref<SharedObject>::adopt(static_cast<SharedObject*>(copy)), true});
}

void CustomWrite::writeData(const Data& data)
{
    Encoder& out = m_context.out();
    out.begin(data.customClass->type(), data.customClass->name().c_str());
    const std::size_t start = out.position();
    if (auto write = data.customClass->methodAs<TQ3XObjectWriteMethod>(kQ3XMethodTypeObjectWrite)) {
        TQ3FileObject file = m_context.fileHandle();
        if (file == nullptr)
            fail(kQ3ErrorFileNotOpen, "the file was closed: the write method of \"" + data.customClass->name() +
                                          "\" cannot write to it");
        TQ3Status status;
        m_context.enterMethod();
        try {
            status = write(data.data, file);
        } catch (...) {
            m_context.leaveMethod();
            throw;
        }
        m_context.leaveMethod();
        if (status != kQ3Success)
            fail(kQ3ErrorInvalidParameter, "the write method of the class \"" + data.customClass->name() + "\" failed");
        if (out.encoding() != Encoding::kText) {
            const std::size_t written = out.position() - start;
            if (written > data.size)
                fail(kQ3ErrorWroteMoreThanSize, "the write method of \"" + data.customClass->name() + "\" wrote " +
                                                    std::to_string(written) + " bytes, more than the " +
                                                    std::to_string(data.size) + " its traverse method submitted");
            if (written < data.size)
                fail(kQ3ErrorWroteLessThanSize, "the write method of \"" + data.customClass->name() + "\" wrote " +
                                                    std::to_string(written) + " bytes, less than the " +
                                                    std::to_string(data.size) + " its traverse method submitted");
        }
    }
    out.end();
}

void CustomWrite::write()
{
    if (!m_own)
        return;
    maybeContainer(m_context, !m_subs.empty(), [&] {
        writeData(*m_own);
        for (Sub& sub : m_subs) {
            if (sub.data)
                writeData(*sub.data);
            else if (sub.temporary)
                m_context.temporary(*sub.object);
            else
                m_context.object(*sub.object);
        }
    });
}

const CustomClass* customWriterOf(const Object& object)
{
    CustomInstance* instance = customInstanceOf(const_cast<Object&>(object));
    if (instance == nullptr)
        return nullptr;
    const CustomClass& leaf = instance->customClass();
    return leaf.method(kQ3XMethodTypeObjectTraverse) != nullptr ? &leaf : nullptr;
}

void writeCustomObject(WriteContext& context, const Object& object)
{
    auto& target = const_cast<Object&>(object);
    CustomInstance& instance = *customInstanceOf(target);
    const CustomClass& leaf = instance.customClass();
    auto traverse = leaf.methodAs<TQ3XObjectTraverseMethod>(kQ3XMethodTypeObjectTraverse);
    CustomWrite collector(context, registered(leaf));
    runTraverse(context, collector, leaf,
                [&] { return traverse(&target, instance.privateData(leaf), context.view()); });
    collector.write();
}

bool writesCustomElements(const CustomClass& elementClass)
{
    return elementTraverse(elementClass) != nullptr;
}

bool writeCustomElement(WriteContext& context, const CustomElement& element)
{
    const CustomClass& elementClass = element.elementClass();
    TQ3XObjectTraverseMethod traverse = elementTraverse(elementClass);
    if (traverse == nullptr)
        return false;
    CustomWrite collector(context, registered(elementClass));
    // Apple's traverse methods take the element's data as void*.
    void* data = const_cast<void*>(element.data());
    runTraverse(context, collector, elementClass, [&] { return traverse(nullptr, data, context.view()); });
    collector.write();
    return true;
}

CustomWrite& activeCustomWrite(TQ3ViewObject view)
{
    if (t_active.empty() || t_active.back().view != view)
        fail(kQ3ErrorWriteStateInactive, "no traverse method of a custom class is writing through this view");
    return *t_active.back().collector;
}

Ref<SharedObject> readCustomObject(ReadContext& context, const Node& node, const CustomClass& objectClass)
{
    auto read = objectClass.methodAs<TQ3XObjectReadMethod>(kQ3XMethodTypeObjectRead);
    if (read == nullptr || context.fileObject() == nullptr) {
        errors::postWarning(kQ3WarningNoObjectSupportForReadMethod,
                            "the class \"" + objectClass.name() +
                                (read == nullptr ? "\" has no read method (kQ3XMethodTypeObjectRead)"
                                                 : "\" is read only through a file object") +
                                "; the object is read as an unknown object");
        return {};
    }
    File& file = readingFile(context);
    TQ3Object made = nullptr;
    const std::size_t unread = file.readNode(node, [&] { made = read(&file); });
    if (made == nullptr)
        fail(kQ3ErrorInvalidMetafileObject, "the read method of the class \"" + objectClass.name() + "\" failed");
    Object& object = lookupObject(made, "the object the read method returned");
    if (!object.isType(kQ3ObjectTypeShared)) {
        object.dispose();
        fail(kQ3ErrorInvalidMetafileObject, "the read method of the class \"" + objectClass.name() +
                                                "\" returned a " + object.classInfo().name +
                                                ", which is no shared object");
    }
    Ref<SharedObject> result = Ref<SharedObject>::adopt(static_cast<SharedObject*>(&object));
    // Elements the read method left in its container belong to its object,
    // as they do to every other object whose container holds them (what
    // Q3Object_AddElement gave it comes back so).
    if (node.type == kTypeContainer) {
        std::vector<std::unique_ptr<CustomElement>> elements;
        for (std::size_t i = std::max<std::size_t>(unread, 1); i < node.children.size(); ++i)
            readCustomElement(context, node.children[i], elements);
        for (std::unique_ptr<CustomElement>& element : elements)
            result->elements().ownSet().addCustomElement(std::move(element));
    }
    return result;
}

Ref<SharedObject> readElementAsSet(ReadContext& context, const Node& node)
{
    std::vector<std::unique_ptr<CustomElement>> elements;
    if (!readCustomElement(context, node, elements))
        return {};
    Ref<Set> set = makeShared<Set>();
    for (std::unique_ptr<CustomElement>& element : elements)
        set->addCustomElement(std::move(element));
    return Ref<SharedObject>(std::move(set));
}

bool readCustomElementData(ReadContext& context, const Node& node, const CustomClass& elementClass,
                           std::vector<std::unique_ptr<CustomElement>>& made)
{
    auto readData = elementClass.methodAs<TQ3XObjectReadDataMethod>(kQ3XMethodTypeObjectReadData);
    if (readData == nullptr || context.fileObject() == nullptr) {
        errors::postWarning(kQ3WarningNoObjectSupportForReadMethod,
                            "the element class \"" + elementClass.name() +
                                (readData == nullptr ? "\" has no read-data method (kQ3XMethodTypeObjectReadData)"
                                                     : "\" is read only through a file object") +
                                "; the element is left out");
        return false;
    }
    File& file = readingFile(context);
    Ref<Set> elements = makeShared<Set>();
    TQ3Status status = kQ3Failure;
    file.readNode(node, [&] { status = readData(elements.get(), &file); });
    if (status != kQ3Success)
        fail(kQ3ErrorInvalidMetafileObject,
             "the read-data method of the element class \"" + elementClass.name() + "\" failed");
    for (std::unique_ptr<CustomElement>& element : elements->takeCustomElements())
        made.push_back(std::move(element));
    return true;
}

} // namespace q3::io
