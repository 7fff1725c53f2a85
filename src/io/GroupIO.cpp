// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Groups: `BeginGroup ( DisplayGroup ( ) )`, the group's objects, then
// `EndGroup ( )` (3D Metafile Reference, "Group objects"). The objects are
// collected by ReadContext::sequenceItem; here is only the group itself.
// Also the unknown objects, written back as they were read.

#include "io/ClassIO.h"

#include "core/ErrorManager.h"
#include "group/Group.h"
#include "io/Unknown.h"

namespace q3::io {
namespace {

template <class G>
Ref<SharedObject> readGroup(ReadContext&, const Parts&)
{
    return Ref<SharedObject>(makeShared<G>());
}

void writeGroup(WriteContext& context, const Object& object, TQ3ObjectType type, const char* name)
{
    const auto& group = static_cast<const Group&>(object);
    Encoder& out = context.out();
    out.begin(kTypeBeginGroup, "BeginGroup");
    out.begin(type, name);
    out.end();
    out.end();
    for (const Group::Node& node : group.nodes())
        context.object(*node.object);
    out.begin(kTypeEndGroup, "EndGroup");
    out.end();
}

void writePlainGroup(WriteContext& c, const Object& o)
{
    writeGroup(c, o, kQ3ShapeTypeGroup, "Group");
}
void writeDisplayGroup(WriteContext& c, const Object& o)
{
    writeGroup(c, o, kQ3GroupTypeDisplay, "DisplayGroup");
}
void writeOrderedGroup(WriteContext& c, const Object& o)
{
    writeGroup(c, o, kQ3DisplayGroupTypeOrdered, "OrderedDisplayGroup");
}
void writeIOProxyGroup(WriteContext& c, const Object& o)
{
    writeGroup(c, o, kQ3DisplayGroupTypeIOProxy, "IOProxyDisplayGroup");
}
void writeLightGroup(WriteContext& c, const Object& o)
{
    writeGroup(c, o, kQ3GroupTypeLight, "LightGroup");
}
void writeInfoGroup(WriteContext& c, const Object& o)
{
    writeGroup(c, o, kQ3GroupTypeInfo, "InfoGroup");
}

Ref<SharedObject> readUnknownTag(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject, "an object typed as an unknown object (" + typeName(parts.root.type) + ")");
}

void writeUnknownText(WriteContext& context, const Object& object)
{
    const auto& unknown = static_cast<const UnknownText&>(object);
    Encoder& out = context.out();
    if (out.encoding() != Encoding::kText) {
        errors::postWarning(kQ3WarningNoObjectSupportForWriteMethod,
                            "an unknown text object (" + unknown.name() + ") has no binary form; it is left out");
        return;
    }
    out.begin(0, unknown.name().c_str());
    out.raw(unknown.contents());
    out.end();
}

void writeUnknownBinary(WriteContext& context, const Object& object)
{
    const auto& unknown = static_cast<const UnknownBinary&>(object);
    Encoder& out = context.out();
    if (out.encoding() == Encoding::kText) {
        errors::postWarning(kQ3WarningNoObjectSupportForWriteMethod,
                            "an unknown binary object (" + typeName(unknown.type()) +
                                ") has no text form; it is left out");
        return;
    }
    out.begin(unknown.type(), "");
    out.raw(unknown.contents());
    out.end();
}

} // namespace

void addGroupClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(),
                 {
                     {kQ3ShapeTypeGroup, "Group", readGroup<Group>, writePlainGroup},
                     {kQ3GroupTypeDisplay, "DisplayGroup", readGroup<DisplayGroup>, writeDisplayGroup},
                     {kQ3DisplayGroupTypeOrdered, "OrderedDisplayGroup", readGroup<OrderedDisplayGroup>,
                      writeOrderedGroup},
                     {kQ3DisplayGroupTypeIOProxy, "IOProxyDisplayGroup", readGroup<IOProxyDisplayGroup>,
                      writeIOProxyGroup},
                     {kQ3GroupTypeLight, "LightGroup", readGroup<LightGroup>, writeLightGroup},
                     {kQ3GroupTypeInfo, "InfoGroup", readGroup<InfoGroup>, writeInfoGroup},
                     {kQ3UnknownTypeText, "UnknownText", readUnknownTag, writeUnknownText},
                     {kQ3UnknownTypeBinary, "UnknownBinary", readUnknownTag, writeUnknownBinary},
                 });
}

} // namespace q3::io
