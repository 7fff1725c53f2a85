// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Groups: `BeginGroup ( DisplayGroup ( ) )`, the group's objects, then
// `EndGroup ( )` (3D Metafile Reference, "Group objects"). The objects are
// collected by ReadContext::sequenceItem; here is only the group itself.
// Also the unknown objects, written back as they were read.

#include "io/ClassIO.h"

#include "core/CustomObject.h"
#include "core/ErrorManager.h"
#include "group/Group.h"
#include "io/CustomElements.h"
#include "io/CustomIO.h"
#include "io/Unknown.h"

#include <type_traits>

namespace q3::io {
namespace {

// A display group's state, when not the default, is a DisplayGroupState
// subobject whose flags say what differs from the default: Inline 1,
// DoNotDraw 2, NoBoundingBox 4, NoBoundingSphere 8, DoNotPick 16 (Apple's
// MF3D parser, kMF3DObjDisplayGroupState, for the bits; the words are
// Quesa's: the reference spells the first "IsInline" while QuickDraw 3D
// writes "Inline"). Q3 writes the first word of each bit and reads the
// others too: "IsInline", and "DontDraw" / "DontPick", which Q3 wrote before.
constexpr TQ3ObjectType kTypeGroupState = kTypeDisplayGroupState;
const std::vector<std::pair<const char*, std::uint32_t>> kStateFlags = {
    {"None", 0},       {"Inline", 1},    {"DoNotDraw", 2}, {"NoBoundingBox", 4}, {"NoBoundingSphere", 8},
    {"DoNotPick", 16}, {"IsInline", 1},  {"DontDraw", 2},  {"DontPick", 16}};

constexpr TQ3DisplayGroupState kDefaultState = kQ3DisplayGroupStateMaskIsDrawn |
                                               kQ3DisplayGroupStateMaskUseBoundingBox |
                                               kQ3DisplayGroupStateMaskUseBoundingSphere |
                                               kQ3DisplayGroupStateMaskIsPicked | kQ3DisplayGroupStateMaskIsWritten;

std::uint32_t fileFlags(TQ3DisplayGroupState state)
{
    std::uint32_t flags = 0;
    if (state & kQ3DisplayGroupStateMaskIsInline)
        flags |= 1;
    if (!(state & kQ3DisplayGroupStateMaskIsDrawn))
        flags |= 2;
    if (!(state & kQ3DisplayGroupStateMaskUseBoundingBox))
        flags |= 4;
    if (!(state & kQ3DisplayGroupStateMaskUseBoundingSphere))
        flags |= 8;
    if (!(state & kQ3DisplayGroupStateMaskIsPicked))
        flags |= 16;
    return flags;
}

TQ3DisplayGroupState stateOf(std::uint32_t flags)
{
    TQ3DisplayGroupState state = kDefaultState;
    if (flags & 1)
        state |= kQ3DisplayGroupStateMaskIsInline;
    if (flags & 2)
        state &= ~kQ3DisplayGroupStateMaskIsDrawn;
    if (flags & 4)
        state &= ~kQ3DisplayGroupStateMaskUseBoundingBox;
    if (flags & 8)
        state &= ~kQ3DisplayGroupStateMaskUseBoundingSphere;
    if (flags & 16)
        state &= ~kQ3DisplayGroupStateMaskIsPicked;
    return state;
}

template <class G>
Ref<SharedObject> readGroup(ReadContext& context, const Parts& parts)
{
    Ref<G> group = makeShared<G>();
    for (const Node* node : parts.subobjects)
        readGroupSubobject(context, *group, *node);
    return Ref<SharedObject>(std::move(group));
}

Ref<SharedObject> refuseState(ReadContext&, const Parts&)
{
    fail(kQ3ErrorInvalidMetafileObject, "DisplayGroupState outside a display group");
}

void writeGroup(WriteContext& context, const Object& object, TQ3ObjectType type, const char* name)
{
    const auto& group = static_cast<const Group&>(object);
    Encoder& out = context.out();
    // As Apple's tools write it: the group object and, when it is not the
    // default, its DisplayGroupState side by side in the BeginGroup.
    std::uint32_t flags = 0;
    if (group.isType(kQ3GroupTypeDisplay)) {
        const TQ3DisplayGroupState state = static_cast<const DisplayGroup&>(group).state();
        // The QD3D Book's kQ3DisplayGroupStateMaskIsWritten: a display group
        // without it is left out of files, with everything in it.
        if (!(state & kQ3DisplayGroupStateMaskIsWritten))
            return;
        flags = fileFlags(state);
    }
    out.begin(kTypeBeginGroup, "BeginGroup");
    // A group class an application registered: its own name, and its data
    // when its class writes any (its traverse method).
    const CustomInstance* custom = customInstanceOf(const_cast<Object&>(object));
    if (custom != nullptr && customWriterOf(object) != nullptr) {
        writeCustomObject(context, object);
    } else {
        out.begin(custom ? custom->customClass().type() : type,
                  custom ? custom->customClass().name().c_str() : name);
        out.end();
    }
    if (flags != 0) {
        out.begin(kTypeGroupState, "DisplayGroupState");
        out.flags(kStateFlags, flags);
        out.end();
    }
    for (const Ref<SharedObject>& element : group.otherElements())
        context.object(*element);
    // Its name and URL elements beside its state, as Quesa's test models
    // hold them (io/CustomElements.h).
    if (const ObjectElements* elements = group.elementsIfAny(); elements != nullptr && elements->own)
        writeCustomElements(context, *elements->own);
    out.end();
    out.enterGroup();
    for (const Group::Node& node : group.nodes())
        context.object(*node.object);
    out.leaveGroup();
    out.begin(kTypeEndGroup, "EndGroup");
    out.end();
}

// The writer of a group of class `Type`, under the text name of its row.
template <TQ3ObjectType Type>
void writeGroupOf(WriteContext& context, const Object& object)
{
    writeGroup(context, object, Type, classOfType(Type)->name);
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
    // Its data cannot be swapped without knowing their layout.
    const TQ3Endian order = out.encoding() == Encoding::kBinaryLittle ? kQ3EndianLittle : kQ3EndianBig;
    if (unknown.byteOrder() != order) {
        errors::postWarning(kQ3WarningNoObjectSupportForWriteMethod,
                            "an unknown binary object (" + typeName(unknown.type()) +
                                ") came from a file of the other byte order; it is left out");
        return;
    }
    // A custom type is declared again under the name its file gave it.
    out.begin(unknown.type(), unknown.typeString().c_str());
    out.rawObjects(unknown.contents(), unknown.declaredTypes());
    out.end();
}

} // namespace

void readGroupSubobject(ReadContext& context, Group& group, const Node& node)
{
    if (node.type == kTypeGroupState) {
        applyGroupState(context, group, node);
        return;
    }
    // An element Q3 has no class for (Apple's name element in its
    // container, say) is kept as the unknown object it reads as and
    // written back; anything else is no part of a group.
    Ref<SharedObject> element = context.object(node);
    if (element->isType(kQ3ShapeTypeUnknown)) {
        errors::postWarning(kQ3WarningUnknownElementType,
                            std::string("a ") + group.classInfo().name + " holds " +
                                (node.name.empty() ? typeName(node.type) : node.name) +
                                ", an element Q3 does not know; it is kept as an unknown object and written back");
        group.addOtherElement(std::move(element));
    } else {
        errors::postWarning(kQ3WarningInvalidSubObjectForObject,
                            std::string("a ") + group.classInfo().name + " holds a " + element->classInfo().name +
                                ", which is no part of a group; it is left out");
    }
}

void applyGroupState(ReadContext& context, SharedObject& group, const Node& state)
{
    DataReader in = context.reader(state);
    const std::uint32_t flags = in.flags(kStateFlags);
    if (!group.isType(kQ3GroupTypeDisplay)) {
        errors::postWarning(kQ3WarningInvalidSubObjectForObject,
                            std::string("a ") + group.classInfo().name +
                                " has a DisplayGroupState, which only display groups have; it is ignored");
        return;
    }
    static_cast<DisplayGroup&>(group).setState(stateOf(flags));
}

void addGroupClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(),
                 {
                     {kQ3ShapeTypeGroup, "Group", readGroup<Group>, writeGroupOf<kQ3ShapeTypeGroup>},
                     // Apple's 1995 metafile parser (MF3D, kMF3DObjGroup)
                     // types a plain group 'grop'; QD3D.h's kQ3ShapeTypeGroup
                     // is 'grup', which Q3 writes. Read both.
                     {Q3_OBJECT_TYPE('g', 'r', 'o', 'p'), "Group", readGroup<Group>, writeGroupOf<kQ3ShapeTypeGroup>},
                     {kQ3GroupTypeDisplay, "DisplayGroup", readGroup<DisplayGroup>, writeGroupOf<kQ3GroupTypeDisplay>},
                     {kQ3DisplayGroupTypeOrdered, "OrderedDisplayGroup", readGroup<OrderedDisplayGroup>,
                      writeGroupOf<kQ3DisplayGroupTypeOrdered>},
                     {kQ3DisplayGroupTypeIOProxy, "IOProxyDisplayGroup", readGroup<IOProxyDisplayGroup>,
                      writeGroupOf<kQ3DisplayGroupTypeIOProxy>},
                     {kQ3GroupTypeLight, "LightGroup", readGroup<LightGroup>, writeGroupOf<kQ3GroupTypeLight>},
                     {kQ3GroupTypeInfo, "InfoGroup", readGroup<InfoGroup>, writeGroupOf<kQ3GroupTypeInfo>},
                     {kTypeGroupState, "DisplayGroupState", refuseState, [](WriteContext&, const Object&) {}},
                     {kQ3UnknownTypeText, "UnknownText", readUnknownTag, writeUnknownText},
                     {kQ3UnknownTypeBinary, "UnknownBinary", readUnknownTag, writeUnknownBinary},
                 });
}

} // namespace q3::io
