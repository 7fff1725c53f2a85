// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The Q3ObjectHierarchy_ queries of QD3D.h, answered from the class registry
// (core/Object.h): every ClassInfo is a registered class. A class's name is
// its 3DMF text name (io/ClassIO.h) where it has one, since QuickDraw 3D's
// metafile writes a class by its class name; else its description with the
// words joined and capitalized ("interactive renderer" -> "InteractiveRenderer").
#include "QD3D.h"

#include "api/Entry.h"
#include "core/CustomClass.h"
#include "io/ClassIO.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

namespace {

std::string classNameOf(const ClassInfo& info)
{
    if (const std::shared_ptr<CustomClass> custom = findCustomClass(info.type))
        return custom->name();
    if (const io::ClassIO* entry = io::classOfType(info.type))
        return entry->name;
    std::string name;
    bool wordStart = true;
    for (const char* c = info.name; *c != '\0'; ++c) {
        if (*c == ' ') {
            wordStart = true;
            continue;
        }
        name += wordStart ? static_cast<char>(std::toupper(static_cast<unsigned char>(*c))) : *c;
        wordStart = false;
    }
    return name;
}

const ClassInfo* classNamed(const char* name)
{
    for (const ClassInfo* info : allClasses())
        if (classNameOf(*info) == name)
            return info;
    return nullptr;
}

const ClassInfo& registeredClass(TQ3ObjectType type, const char* parameter)
{
    const ClassInfo* info = type == kQ3ObjectTypeInvalid ? nullptr : findClass(type);
    if (info == nullptr)
        fail(kQ3ErrorInvalidParameter, std::string(parameter) + " " + std::to_string(type) + " is not a registered class");
    return *info;
}

} // namespace

extern "C" {

TQ3Status Q3ObjectHierarchy_GetTypeFromString(TQ3ObjectClassNameString objectClassString,
                                              TQ3ObjectType* objectClassType)
{
    return guardStatus(__func__, [&] {
        requireNonNull(objectClassString, "objectClassString");
        requireNonNull(objectClassType, "objectClassType");
        const ClassInfo* info = classNamed(objectClassString);
        if (info == nullptr)
            fail(kQ3ErrorInvalidParameter, std::string("no class is named \"") + objectClassString + "\"");
        *objectClassType = info->type;
    });
}

TQ3Status Q3ObjectHierarchy_GetStringFromType(TQ3ObjectType objectClassType,
                                              TQ3ObjectClassNameString objectClassString)
{
    return guardStatus(__func__, [&] {
        const std::string name = classNameOf(registeredClass(objectClassType, "objectClassType"));
        requireNonNull(objectClassString, "objectClassString");
        const std::size_t length = std::min<std::size_t>(name.size(), kQ3StringMaximumLength - 1);
        std::memcpy(objectClassString, name.data(), length);
        objectClassString[length] = '\0';
    });
}

TQ3Boolean Q3ObjectHierarchy_IsTypeRegistered(TQ3ObjectType objectClassType)
{
    return guard(__func__, kQ3False, [&] {
        return objectClassType != kQ3ObjectTypeInvalid && findClass(objectClassType) != nullptr ? kQ3True
                                                                                                 : kQ3False;
    });
}

TQ3Boolean Q3ObjectHierarchy_IsNameRegistered(const char* objectClassName)
{
    return guard(__func__, kQ3False, [&] {
        requireNonNull(objectClassName, "objectClassName");
        return classNamed(objectClassName) != nullptr ? kQ3True : kQ3False;
    });
}

TQ3Status Q3ObjectHierarchy_GetSubClassData(TQ3ObjectType objectClassType, TQ3SubClassData* subClassData)
{
    return guardStatus(__func__, [&] {
        const ClassInfo& parent = registeredClass(objectClassType, "objectClassType");
        requireNonNull(subClassData, "subClassData");
        std::vector<TQ3ObjectType> types;
        for (const ClassInfo* info : allClasses())
            if (info->parent == &parent)
                types.push_back(info->type);
        TQ3ObjectType* array = nullptr;
        if (!types.empty()) {
            array = static_cast<TQ3ObjectType*>(std::malloc(types.size() * sizeof(TQ3ObjectType)));
            if (array == nullptr)
                throw std::bad_alloc();
            std::memcpy(array, types.data(), types.size() * sizeof(TQ3ObjectType));
        }
        subClassData->numClasses = types.size();
        subClassData->classTypes = array;
    });
}

TQ3Status Q3ObjectHierarchy_EmptySubClassData(TQ3SubClassData* subClassData)
{
    return guardStatus(__func__, [&] {
        requireNonNull(subClassData, "subClassData");
        std::free(subClassData->classTypes);
        subClassData->classTypes = nullptr;
        subClassData->numClasses = 0;
    });
}

} // extern "C"
