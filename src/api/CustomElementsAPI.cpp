// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// QD3DCustomElements.h: the name and URL elements of any object, through the
// element calls every object takes (ElementEntry.h) and the two classes
// io/CustomElements.h registers.
#include "QD3DCustomElements.h"
#include "api/ElementEntry.h"
#include "api/Entry.h"
#include "core/EnumValue.h"
#include "io/CustomElements.h"
#include "io/StringObject.h"

#include <cstdlib>

using namespace q3;
using namespace q3::api::elements;
using namespace q3::api;

extern "C" {

TQ3Status CENameElement_SetData(TQ3Object object, const char* name)
{
    return guardStatus(__func__, [&] {
        const TQ3ElementType type = io::nameElementClass()->type();
        lookupObject(object, "object");
        if (name == nullptr) {
            if (containsElement(object, Family::kObject, type))
                clearElement(object, Family::kObject, type);
            return;
        }
        Ref<CString> text = makeShared<CString>(name);
        TQ3Object handle = text.get();
        addElement(object, Family::kObject, type, &handle);
    });
}

TQ3Status CENameElement_GetData(TQ3Object object, char** name)
{
    return guardStatus(__func__, [&] {
        const TQ3ElementType type = io::nameElementClass()->type();
        lookupObject(object, "object");
        requireNonNull(name, "name");
        if (!containsElement(object, Family::kObject, type)) {
            *name = nullptr;
            return;
        }
        TQ3Object handle = nullptr;
        getElement(object, Family::kObject, type, &handle);
        Ref<CString> text = Ref<CString>::adopt(static_cast<CString*>(static_cast<Object*>(handle)));
        *name = mallocCopy(text->text());
    });
}

TQ3Status CENameElement_EmptyData(char** name)
{
    return guardStatus(__func__, [&] {
        requireNonNull(name, "name");
        std::free(*name);
        *name = nullptr;
    });
}

TQ3Status CEUrlElement_SetData(TQ3Object object, TCEUrlData* urlData)
{
    return guardStatus(__func__, [&] {
        const TQ3ElementType type = io::urlElementClass()->type();
        lookupObject(object, "object");
        if (urlData == nullptr) {
            if (containsElement(object, Family::kObject, type))
                clearElement(object, Family::kObject, type);
            return;
        }
        requireNonNull(urlData->url, "urlData->url");
        const long options = enumValue(urlData->options);
        if (options != kCEUrlOptionNone && options != kCEUrlOptionUseMap)
            fail(kQ3ErrorInvalidParameter, "urlData->options is " + std::to_string(options) +
                                               ", neither kCEUrlOptionNone nor kCEUrlOptionUseMap");
        addElement(object, Family::kObject, type, &urlData);
    });
}

TQ3Status CEUrlElement_GetData(TQ3Object object, TCEUrlData** urlData)
{
    return guardStatus(__func__, [&] {
        const TQ3ElementType type = io::urlElementClass()->type();
        lookupObject(object, "object");
        requireNonNull(urlData, "urlData");
        if (!containsElement(object, Family::kObject, type)) {
            *urlData = nullptr;
            return;
        }
        getElement(object, Family::kObject, type, urlData);
    });
}

TQ3Status CEUrlElement_EmptyData(TCEUrlData** urlData)
{
    return guardStatus(__func__, [&] {
        requireNonNull(urlData, "urlData");
        if (*urlData != nullptr) {
            std::free((*urlData)->url);
            std::free((*urlData)->description);
            std::free(*urlData);
        }
        *urlData = nullptr;
    });
}

} // extern "C"
