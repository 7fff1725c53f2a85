// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/CustomElements.h"

#include "QD3DSet.h"
#include "core/AttributeSet.h"
#include "core/EnumValue.h"
#include "core/ErrorManager.h"
#include "io/ClassIO.h"
#include "io/CustomIO.h"
#include "io/StringObject.h"

#include <cstdlib>
#include <cstring>
#include <mutex>

namespace q3::io {
namespace {

// ---- The name element: internally a reference to a C string object.

TQ3Object handleAt(const void* data)
{
    TQ3Object handle;
    std::memcpy(&handle, data, sizeof handle);
    return handle;
}

void storeHandle(void* data, TQ3Object handle)
{
    std::memcpy(data, &handle, sizeof handle);
}

// Methods report failure by their status alone: the call running them posts
// the one error.
TQ3Status nameCopyAdd(const void* fromAPI, void* toInternal)
{
    try {
        storeHandle(toInternal, lookupRef<CString>(handleAt(fromAPI), "the name").detach());
        return kQ3Success;
    } catch (const Error&) {
        return kQ3Failure;
    }
}

TQ3Status nameDelete(void* internal)
{
    if (TQ3Object handle = handleAt(internal))
        static_cast<CString*>(static_cast<Object*>(handle))->releaseReference();
    storeHandle(internal, nullptr);
    return kQ3Success;
}

TQ3Status nameCopyReplace(const void* fromAPI, void* ontoInternal)
{
    TQ3Object old = handleAt(ontoInternal);
    if (nameCopyAdd(fromAPI, ontoInternal) != kQ3Success)
        return kQ3Failure;
    TQ3Object replaced = old;
    return nameDelete(&replaced);
}

TQ3Status nameCopyGet(const void* fromInternal, void* toAPI)
{
    auto* text = static_cast<CString*>(static_cast<Object*>(handleAt(fromInternal)));
    text->addReference();
    storeHandle(toAPI, text);
    return kQ3Success;
}

TQ3Status nameCopyDuplicate(const void* fromInternal, void* toInternal)
{
    const auto* text = static_cast<const CString*>(static_cast<Object*>(handleAt(fromInternal)));
    storeHandle(toInternal, makeShared<CString>(text->text()).detach());
    return kQ3Success;
}

TQ3XFunctionPointer nameMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeElementCopyAdd:
        return reinterpret_cast<TQ3XFunctionPointer>(nameCopyAdd);
    case kQ3XMethodTypeElementCopyReplace:
        return reinterpret_cast<TQ3XFunctionPointer>(nameCopyReplace);
    case kQ3XMethodTypeElementCopyGet:
        return reinterpret_cast<TQ3XFunctionPointer>(nameCopyGet);
    case kQ3XMethodTypeElementCopyDuplicate:
        return reinterpret_cast<TQ3XFunctionPointer>(nameCopyDuplicate);
    case kQ3XMethodTypeElementDelete:
        return reinterpret_cast<TQ3XFunctionPointer>(nameDelete);
    default:
        return nullptr;
    }
}

// ---- The URL element: internally UrlElementData with malloc'ed strings.

char* copyOf(const char* text)
{
    if (text == nullptr)
        return nullptr;
    const std::size_t size = std::strlen(text) + 1;
    char* copy = static_cast<char*>(std::malloc(size));
    if (copy != nullptr)
        std::memcpy(copy, text, size);
    return copy;
}

TQ3Status urlDelete(void* internal)
{
    auto* data = static_cast<UrlElementData*>(internal);
    std::free(data->url);
    std::free(data->description);
    data->url = nullptr;
    data->description = nullptr;
    return kQ3Success;
}

TQ3Status urlFill(const UrlElementData& from, UrlElementData& to)
{
    UrlElementData made{copyOf(from.url), copyOf(from.description), from.options};
    if (made.url == nullptr || (from.description != nullptr && made.description == nullptr)) {
        urlDelete(&made);
        return kQ3Failure;
    }
    to = made;
    return kQ3Success;
}

TQ3Status urlCopyAdd(const void* fromAPI, void* toInternal)
{
    const TCEUrlData* given;
    std::memcpy(&given, fromAPI, sizeof given);
    if (given == nullptr || given->url == nullptr)
        return kQ3Failure;
    const long options = enumValue(given->options);
    if (options != kCEUrlOptionNone && options != kCEUrlOptionUseMap)
        return kQ3Failure;
    return urlFill(UrlElementData{given->url, given->description, static_cast<std::uint32_t>(options)},
                   *static_cast<UrlElementData*>(toInternal));
}

TQ3Status urlCopyReplace(const void* fromAPI, void* ontoInternal)
{
    UrlElementData fresh{};
    if (urlCopyAdd(fromAPI, &fresh) != kQ3Success)
        return kQ3Failure;
    urlDelete(ontoInternal);
    *static_cast<UrlElementData*>(ontoInternal) = fresh;
    return kQ3Success;
}

TQ3Status urlCopyGet(const void* fromInternal, void* toAPI)
{
    const auto& from = *static_cast<const UrlElementData*>(fromInternal);
    auto* out = static_cast<TCEUrlData*>(std::malloc(sizeof(TCEUrlData)));
    if (out == nullptr)
        return kQ3Failure;
    UrlElementData copy{};
    if (urlFill(from, copy) != kQ3Success) {
        std::free(out);
        return kQ3Failure;
    }
    out->url = copy.url;
    out->description = copy.description;
    out->options = copy.options == kCEUrlOptionUseMap ? kCEUrlOptionUseMap : kCEUrlOptionNone;
    std::memcpy(toAPI, &out, sizeof out);
    return kQ3Success;
}

TQ3Status urlCopyDuplicate(const void* fromInternal, void* toInternal)
{
    return urlFill(*static_cast<const UrlElementData*>(fromInternal), *static_cast<UrlElementData*>(toInternal));
}

TQ3XFunctionPointer urlMetaHandler(TQ3XMethodType type)
{
    switch (type) {
    case kQ3XMethodTypeElementCopyAdd:
        return reinterpret_cast<TQ3XFunctionPointer>(urlCopyAdd);
    case kQ3XMethodTypeElementCopyReplace:
        return reinterpret_cast<TQ3XFunctionPointer>(urlCopyReplace);
    case kQ3XMethodTypeElementCopyGet:
        return reinterpret_cast<TQ3XFunctionPointer>(urlCopyGet);
    case kQ3XMethodTypeElementCopyDuplicate:
        return reinterpret_cast<TQ3XFunctionPointer>(urlCopyDuplicate);
    case kQ3XMethodTypeElementDelete:
        return reinterpret_cast<TQ3XFunctionPointer>(urlDelete);
    default:
        return nullptr;
    }
}

std::mutex& registrationMutex()
{
    static auto* mutex = new std::mutex;
    return *mutex;
}

std::shared_ptr<CustomClass> ensure(const char* name, std::size_t size, TQ3XMetaHandler metaHandler)
{
    std::lock_guard<std::mutex> lock(registrationMutex());
    if (std::shared_ptr<CustomClass> found = findCustomClassNamed(name))
        return found;
    return registerCustomClass(CustomClass::Kind::kElement, kQ3ObjectTypeInvalid, kQ3ObjectTypeElement, name, size,
                               metaHandler, nullptr);
}

const std::vector<std::pair<const char*, std::uint32_t>> kUrlOptions = {{"None", kCEUrlOptionNone},
                                                                       {"UseMap", kCEUrlOptionUseMap}};

// The node itself, or the root of the container it is.
const Node& rootOf(const Node& node)
{
    return node.type == kTypeContainer && !node.children.empty() ? node.children.front() : node;
}

std::string descriptionOf(ReadContext& context, const Node& node)
{
    for (std::size_t i = 1; node.type == kTypeContainer && i < node.children.size(); ++i)
        if (node.children[i].type == kQ3StringTypeCString) {
            DataReader in = context.reader(node.children[i]);
            return in.string();
        }
    fail(kQ3ErrorInvalidMetafileObject, std::string("a ") + CEcNameElementName + " without its CString");
}

} // namespace

void registerCustomElements()
{
    nameElementClass();
    urlElementClass();
}

std::shared_ptr<CustomClass> nameElementClass()
{
    return ensure(CEcNameElementName, sizeof(TQ3Object), nameMetaHandler);
}

std::shared_ptr<CustomClass> urlElementClass()
{
    return ensure(CEcUrlElementName, sizeof(UrlElementData), urlMetaHandler);
}

bool readCustomElement(ReadContext& context, const Node& node, std::vector<std::unique_ptr<CustomElement>>& made)
{
    const Node& root = rootOf(node);
    if (root.type == 0 || root.type == kTypeContainer)
        return false;
    const std::shared_ptr<CustomClass> custom = findCustomClass(root.type);
    if (!custom || custom->kind() == CustomClass::Kind::kObject)
        return false;
    if (custom->name() == CEcNameElementName) {
        Ref<CString> text = makeShared<CString>(descriptionOf(context, node));
        TQ3Object handle = text.get();
        made.push_back(std::make_unique<CustomElement>(custom, &handle));
        return true;
    }
    if (custom->name() == CEcUrlElementName) {
        DataReader in = context.reader(root);
        const std::string url = in.string();
        const std::uint32_t options = in.atEnd() ? 0 : in.choice(kUrlOptions);
        if (options > kCEUrlOptionUseMap)
            fail(kQ3ErrorInvalidMetafileObject, "a URL element's options are " + std::to_string(options));
        std::string description;
        const bool described = node.type == kTypeContainer && node.children.size() > 1;
        if (described)
            description = descriptionOf(context, node);
        TCEUrlData data{const_cast<char*>(url.c_str()), described ? const_cast<char*>(description.c_str()) : nullptr,
                        options == kCEUrlOptionUseMap ? kCEUrlOptionUseMap : kCEUrlOptionNone};
        TCEUrlData* pointer = &data;
        made.push_back(std::make_unique<CustomElement>(custom, &pointer));
        return true;
    }
    return readCustomElementData(context, node, *custom, made);
}

bool hasFileElements(const Set* set)
{
    if (set == nullptr)
        return false;
    for (const auto& [type, element] : set->customElements())
        if (element->elementClass().name() == CEcNameElementName ||
            element->elementClass().name() == CEcUrlElementName || writesCustomElements(element->elementClass()))
            return true;
    return false;
}

void writeCustomElements(WriteContext& context, const Set& set)
{
    Encoder& out = context.out();
    for (const auto& [type, element] : set.customElements()) {
        const CustomClass& custom = element->elementClass();
        if (custom.name() == CEcNameElementName) {
            const auto* text = static_cast<const CString*>(static_cast<Object*>(handleAt(element->data())));
            out.begin(kTypeContainer, "Container");
            out.begin(custom.type(), CEcNameElementName);
            out.end();
            out.begin(kQ3StringTypeCString, "CString");
            out.string(text->text());
            out.end();
            out.end();
        } else if (custom.name() == CEcUrlElementName) {
            const auto& data = *static_cast<const UrlElementData*>(element->data());
            const bool described = data.description != nullptr;
            maybeContainer(context, described, [&] {
                out.begin(custom.type(), CEcUrlElementName);
                out.string(data.url);
                out.choice(kUrlOptions, data.options);
                out.end();
                if (described) {
                    out.begin(kQ3StringTypeCString, "CString");
                    out.string(data.description);
                    out.end();
                }
            });
        } else if (!writeCustomElement(context, *element)) {
            errors::postWarning(kQ3WarningNoObjectSupportForWriteMethod,
                                "the element class \"" + custom.name() +
                                    "\" has no 3DMF form in Q3; the element is left out of the file");
        }
    }
}

} // namespace q3::io
