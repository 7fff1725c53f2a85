// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DString.h"

#include "api/Entry.h"
#include "io/StringObject.h"

#include <cstdlib>
#include <cstring>

using namespace q3;
using namespace q3::api;

TQ3ObjectType Q3String_GetType(TQ3StringObject stringObj)
{
    return api::getLeafType<CString>(__func__, stringObj, "stringObj");
}

TQ3StringObject Q3CString_New(const char* str)
{
    return guard(__func__, TQ3StringObject{nullptr}, [&]() -> TQ3StringObject {
        requireNonNull(str, "str");
        return makeShared<CString>(std::string(str)).detach();
    });
}

TQ3Status Q3CString_GetLength(TQ3StringObject stringObj, unsigned long* length)
{
    return getValue<CString>(__func__, stringObj, "stringObj", length, "length",
                             [](const CString& s) { return static_cast<unsigned long>(s.text().size()); });
}

TQ3Status Q3CString_SetString(TQ3StringObject stringObj, const char* str)
{
    return guardStatus(__func__, [&] {
        CString& target = lookup<CString>(stringObj, "stringObj");
        requireNonNull(str, "str");
        target.setText(str);
    });
}

TQ3Status Q3CString_GetString(TQ3StringObject stringObj, char** str)
{
    return guardStatus(__func__, [&] {
        const CString& source = lookup<CString>(stringObj, "stringObj");
        requireNonNull(str, "str");
        const std::string& text = source.text();
        auto* copy = static_cast<char*>(std::malloc(text.size() + 1));
        if (copy == nullptr)
            fail(kQ3ErrorOutOfMemory, "no memory for a copy of the string");
        std::memcpy(copy, text.c_str(), text.size() + 1);
        *str = copy;
    });
}

TQ3Status Q3CString_EmptyData(char** str)
{
    return guardStatus(__func__, [&] {
        requireNonNull(str, "str");
        std::free(*str);
        *str = nullptr;
    });
}
