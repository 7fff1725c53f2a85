// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DIO.h"

#include "api/Entry.h"
#include "core/ParameterChecks.h"
#include "io/Unknown.h"

#include <cstdlib>
#include <cstring>
#include <new>

using namespace q3;
using namespace q3::api;

TQ3ObjectType Q3Unknown_GetType(TQ3UnknownObject unknownObject)
{
    return api::getLeafType<UnknownObject>(__func__, unknownObject, "unknownObject");
}

TQ3Status Q3Unknown_GetDirtyState(TQ3UnknownObject unknownObject, TQ3Boolean* isDirty)
{
    return getValue<UnknownObject>(__func__, unknownObject, "unknownObject", isDirty, "isDirty",
                                   [](const UnknownObject& o) { return o.dirty() ? kQ3True : kQ3False; });
}

TQ3Status Q3Unknown_SetDirtyState(TQ3UnknownObject unknownObject, TQ3Boolean isDirty)
{
    return guardStatus(__func__, [&] {
        lookup<UnknownObject>(unknownObject, "unknownObject").setDirty(booleanOf(isDirty) == kQ3True);
    });
}

TQ3Status Q3UnknownText_GetData(TQ3UnknownObject unknownObject, TQ3UnknownTextData* unknownTextData)
{
    return guardStatus(__func__, [&] {
        const UnknownText& source = lookup<UnknownText>(unknownObject, "unknownObject");
        requireNonNull(unknownTextData, "unknownTextData");
        char* name = mallocCopy(source.name());
        char* contents = nullptr;
        try {
            contents = mallocCopy(source.contents());
        } catch (...) {
            std::free(name);
            throw;
        }
        unknownTextData->objectName = name;
        unknownTextData->contents = contents;
    });
}

TQ3Status Q3UnknownText_EmptyData(TQ3UnknownTextData* unknownTextData)
{
    return guardStatus(__func__, [&] {
        requireNonNull(unknownTextData, "unknownTextData");
        std::free(unknownTextData->objectName);
        std::free(unknownTextData->contents);
        unknownTextData->objectName = nullptr;
        unknownTextData->contents = nullptr;
    });
}

TQ3Status Q3UnknownBinary_GetData(TQ3UnknownObject unknownObject, TQ3UnknownBinaryData* unknownBinaryData)
{
    return guardStatus(__func__, [&] {
        const UnknownBinary& source = lookup<UnknownBinary>(unknownObject, "unknownObject");
        requireNonNull(unknownBinaryData, "unknownBinaryData");
        char* contents = nullptr;
        if (!source.contents().empty()) {
            contents = static_cast<char*>(std::malloc(source.contents().size()));
            if (contents == nullptr)
                throw std::bad_alloc();
            std::memcpy(contents, source.contents().data(), source.contents().size());
        }
        unknownBinaryData->objectType = source.type();
        unknownBinaryData->size = static_cast<unsigned long>(source.contents().size());
        unknownBinaryData->byteOrder = source.byteOrder();
        unknownBinaryData->contents = contents;
    });
}

TQ3Status Q3UnknownBinary_EmptyData(TQ3UnknownBinaryData* unknownBinaryData)
{
    return guardStatus(__func__, [&] {
        requireNonNull(unknownBinaryData, "unknownBinaryData");
        std::free(unknownBinaryData->contents);
        unknownBinaryData->contents = nullptr;
    });
}

TQ3Status Q3UnknownBinary_GetTypeString(TQ3UnknownObject unknownObject, char** typeString)
{
    return guardStatus(__func__, [&] {
        const UnknownBinary& unknown = lookup<UnknownBinary>(unknownObject, "unknownObject");
        requireNonNull(typeString, "typeString");
        if (unknown.typeString().empty()) {
            *typeString = nullptr;
            return;
        }
        const std::string& name = unknown.typeString();
        char* copy = static_cast<char*>(std::malloc(name.size() + 1));
        if (copy == nullptr)
            throw std::bad_alloc();
        std::memcpy(copy, name.c_str(), name.size() + 1);
        *typeString = copy;
    });
}

TQ3Status Q3UnknownBinary_EmptyTypeString(char** typeString)
{
    return guardStatus(__func__, [&] {
        requireNonNull(typeString, "typeString");
        std::free(*typeString);
        *typeString = nullptr;
    });
}
