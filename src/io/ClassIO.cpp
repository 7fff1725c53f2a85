// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/ClassIO.h"

#include "core/CustomClass.h"
#include "core/ErrorManager.h"
#include "core/Limits.h"
#include "group/Group.h"
#include "io/CustomElements.h"
#include "io/CustomIO.h"
#include "core/CustomObject.h"
#include "io/ExternalReference.h"
#include "io/Unknown.h"

#include <cctype>
#include <string>
#include <unordered_map>

namespace q3::io {

const std::vector<ClassIO>& classes()
{
    static const std::vector<ClassIO> table = [] {
        std::vector<ClassIO> all;
        addGeometryClasses(all);
        addAttributeClasses(all);
        addGroupClasses(all);
        addStateClasses(all);
        addCameraClasses(all);
        addPixmapMarkerClasses(all);
        addViewHintsClasses(all);
        addTextureClasses(all);
        addExternalReferenceClasses(all);
        return all;
    }();
    return table;
}

namespace {

// Text names compare without regard to case (the parser asks for every
// object's name), so the name map hashes and compares case-folded
// characters and a lookup copies nothing.
unsigned char folded(char c)
{
    return static_cast<unsigned char>(std::tolower(static_cast<unsigned char>(c)));
}

struct FoldedHash {
    std::size_t operator()(const std::string& name) const
    {
        std::size_t hash = 14695981039346656037ull; // FNV-1a
        for (char c : name)
            hash = (hash ^ folded(c)) * 1099511628211ull;
        return hash;
    }
};

struct FoldedEqual {
    bool operator()(const std::string& a, const std::string& b) const
    {
        if (a.size() != b.size())
            return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (folded(a[i]) != folded(b[i]))
                return false;
        return true;
    }
};

} // namespace

const ClassIO* classOfType(TQ3ObjectType type)
{
    // Built once; a type listed twice keeps its first row, as the scan did.
    static const std::unordered_map<TQ3ObjectType, const ClassIO*> byType = [] {
        std::unordered_map<TQ3ObjectType, const ClassIO*> map;
        for (const ClassIO& entry : classes())
            map.emplace(entry.type, &entry);
        return map;
    }();
    const auto found = byType.find(type);
    return found == byType.end() ? nullptr : found->second;
}

const ClassIO* classOfObject(const Object& object)
{
    for (const ClassInfo* info = &object.classInfo(); info != nullptr; info = info->parent)
        if (const ClassIO* entry = classOfType(info->type))
            return entry;
    return nullptr;
}

TQ3ObjectType typeOfName(const std::string& name)
{
    static const std::unordered_map<std::string, TQ3ObjectType, FoldedHash, FoldedEqual> byName = [] {
        std::unordered_map<std::string, TQ3ObjectType, FoldedHash, FoldedEqual> map;
        for (const ClassIO& entry : classes())
            map.emplace(entry.name, entry.type);
        return map;
    }();
    const auto found = byName.find(name);
    if (found != byName.end())
        return found->second;
    // A class an application registered (or Q3's name and URL elements).
    const std::shared_ptr<CustomClass> custom = findCustomClassNamed(name);
    return custom ? custom->type() : 0;
}

const Node* Parts::find(TQ3ObjectType type) const
{
    for (const Node* node : subobjects) {
        const Node* target = node;
        if (node->type == kTypeReference && file != nullptr) {
            // A reference stands for its target; the caller reads the
            // reference, so every reference gives the one object.
            DataReader in(*file, *node);
            if (in.atEnd())
                continue;
            const auto found = file->references.find(in.u32());
            if (found == file->references.end())
                return node; // reading it reports the dangling reference
            target = found->second;
        }
        if (target->type == type)
            return node;
        if (target->type == kTypeContainer && !target->children.empty() && target->children.front().type == type)
            return node;
    }
    return nullptr;
}

namespace {

struct DepthGuard {
    explicit DepthGuard(std::size_t& depth) : m_depth(depth)
    {
        if (++m_depth > limits::kMaxMetafileNesting) {
            --m_depth;
            fail(kQ3ErrorInvalidMetafile,
                 "objects nest deeper than " + std::to_string(limits::kMaxMetafileNesting) + " levels");
        }
    }
    ~DepthGuard() { --m_depth; }
    std::size_t& m_depth;
};

Ref<SharedObject> unknownFrom(const Metafile& file, const Node& node)
{
    if (file.encoding == Encoding::kText) {
        std::string contents(reinterpret_cast<const char*>(file.bytes.data()) + node.dataBegin,
                             node.dataEnd - node.dataBegin);
        const std::size_t first = contents.find_first_not_of(" \t\r\n");
        const std::size_t last = contents.find_last_not_of(" \t\r\n");
        contents = first == std::string::npos ? std::string() : contents.substr(first, last - first + 1);
        return makeShared<UnknownText>(node.name, std::move(contents));
    }
    std::string contents(reinterpret_cast<const char*>(file.bytes.data()) + node.dataBegin,
                         node.dataEnd - node.dataBegin);
    auto unknown =
        makeShared<UnknownBinary>(node.type, std::move(contents),
                                  file.encoding == Encoding::kBinaryLittle ? kQ3EndianLittle : kQ3EndianBig,
                                  isCustomType(node.type) ? node.name : std::string());
    // The custom types inside (a container's, a group's objects), by the
    // codes the bytes hold, so writing renumbers them (Encoder::rawObjects).
    std::map<std::uint32_t, std::string> declared;
    const auto collect = [&](auto& self, const std::vector<Node>& nodes) -> void {
        for (const Node& child : nodes) {
            if (!child.name.empty() && child.offset + 4 <= file.bytes.size()) {
                const unsigned char* p = file.bytes.data() + child.offset;
                const std::uint32_t code =
                    file.encoding == Encoding::kBinaryLittle
                        ? std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
                              std::uint32_t{p[3]} << 24
                        : std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
                if (isCustomType(static_cast<TQ3ObjectType>(code)))
                    declared[code] = child.name;
            }
            self(self, child.children);
        }
    };
    collect(collect, node.children);
    unknown->setDeclaredTypes(std::move(declared));
    return Ref<SharedObject>(std::move(unknown));
}

// Where the item starting at `index` ends: past its EndGroup for a BeginGroup.
std::size_t itemEnd(const std::vector<Node>& nodes, std::size_t index)
{
    if (nodes[index].type != kTypeBeginGroup)
        return index + 1;
    std::size_t open = 0;
    for (std::size_t i = index; i < nodes.size(); ++i) {
        if (nodes[i].type == kTypeBeginGroup)
            ++open;
        else if (nodes[i].type == kTypeEndGroup && --open == 0)
            return i + 1;
    }
    return nodes.size();
}

// Whether the BeginGroup at index has its own EndGroup (itemEnd gives the
// sequence's end both when that EndGroup is the last node and when there is
// none).
bool groupCloses(const std::vector<Node>& nodes, std::size_t index)
{
    std::size_t open = 0;
    for (std::size_t i = index; i < nodes.size(); ++i) {
        if (nodes[i].type == kTypeBeginGroup)
            ++open;
        else if (nodes[i].type == kTypeEndGroup && --open == 0)
            return true;
    }
    return false;
}

// The sequence (a file's top level or a container's children) that holds
// `node`, and its index there; null when none does.
const std::vector<Node>* sequenceHolding(const std::vector<Node>& nodes, const Node* node, std::size_t& index)
{
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (&nodes[i] == node) {
            index = i;
            return &nodes;
        }
        if (const std::vector<Node>* inside = sequenceHolding(nodes[i].children, node, index))
            return inside;
    }
    return nullptr;
}

// What an object's container holds besides what its class reads: custom
// elements (Apple's name and URL elements, an application's) and objects of
// an application's classes, which their class's attach method attaches.
struct Extras {
    std::vector<std::unique_ptr<CustomElement>> elements;
    std::vector<std::pair<Ref<SharedObject>, TQ3XObjectAttachMethod>> attached;
};

// Takes the extras out of an object's subobjects: they belong to the object,
// not to its class's reader.
Extras takeExtras(ReadContext& context, Parts& parts)
{
    Extras extras;
    for (auto it = parts.subobjects.begin(); it != parts.subobjects.end();) {
        if (readCustomElement(context, **it, extras.elements)) {
            it = parts.subobjects.erase(it);
            continue;
        }
        const Node& node = **it;
        const Node& root = node.type == kTypeContainer && !node.children.empty() ? node.children.front() : node;
        const std::shared_ptr<CustomClass> custom = root.type != 0 ? findCustomClass(root.type) : nullptr;
        if (!custom || custom->kind() != CustomClass::Kind::kObject) {
            ++it;
            continue;
        }
        if (auto attach = custom->methodAs<TQ3XObjectAttachMethod>(kQ3XMethodTypeObjectAttach))
            extras.attached.emplace_back(context.object(node), attach);
        else
            errors::postWarning(kQ3WarningNoAttachMethod, "a " + custom->name() +
                                                              " among an object's subobjects has no attach method "
                                                              "(kQ3XMethodTypeObjectAttach); it is left out");
        it = parts.subobjects.erase(it);
    }
    return extras;
}

void attachExtras(SharedObject& object, Extras extras)
{
    for (auto& [child, attach] : extras.attached)
        if (attach(child.get(), &object) != kQ3Success)
            fail(kQ3ErrorInvalidMetafileObject,
                 std::string("the attach method of the class \"") + child->classInfo().name + "\" failed");
    if (extras.elements.empty())
        return;
    Set& target = object.isType(kQ3SharedTypeSet) ? static_cast<Set&>(object) : object.elements().ownSet();
    for (std::unique_ptr<CustomElement>& element : extras.elements)
        target.addCustomElement(std::move(element));
}

Ref<SharedObject> newCustomGroup(ReadContext& context, const Node& node, const std::shared_ptr<CustomClass>& custom)
{
    const Node& root = node.type == kTypeContainer && !node.children.empty() ? node.children.front() : node;
    if (node.type == kTypeContainer || !context.reader(root).atEnd())
        errors::postWarning(kQ3WarningNoObjectSupportForReadMethod,
                            "the group class \"" + custom->name() +
                                "\" has no read method (kQ3XMethodTypeObjectRead): the data of its own it holds in "
                                "the file are left out");
    return Ref<SharedObject>::adopt(static_cast<SharedObject*>(CustomInstance::make(custom, nullptr)));
}

// An object of an application's class, read by its read method; null when
// it is none or cannot be read so (then it is an unknown object).
Ref<SharedObject> customObjectFrom(ReadContext& context, const Node& node, TQ3ObjectType type)
{
    const std::shared_ptr<CustomClass> custom = type != 0 ? findCustomClass(type) : nullptr;
    if (!custom || custom->kind() != CustomClass::Kind::kObject)
        return {};
    // A group class without a read method is a group with no data of its
    // own: made as Q3XObjectHierarchy_NewObject makes it.
    if (custom->info().isA(kQ3ShapeTypeGroup) && custom->method(kQ3XMethodTypeObjectRead) == nullptr)
        return newCustomGroup(context, node, custom);
    return readCustomObject(context, node, *custom);
}

// An object of an application's class nobody registered: in binary, a
// type the file declares with a Type object (the parser resolves
// registered names to their class's type); in text, an unknown name of the
// form such classes take, "Vendor:Class" (Apple's own "Apple Computer,
// Inc.:NameElement"), which no 3DMF keyword has. Other unknown objects (a
// reserved type or keyword Q3 has no class for) are read without a word.
void warnUnregistered(const Metafile& file, const Node& root)
{
    const bool declared = isCustomType(root.type) && !root.name.empty() && !findCustomClass(root.type);
    const bool named = file.encoding == Encoding::kText && root.type == 0 &&
                       root.name.find(':') != std::string::npos;
    if (declared || named)
        errors::postWarning(kQ3WarningUnknownObject, "no class named \"" + root.name +
                                                         "\" is registered; the object is read as an unknown "
                                                         "object and written back unchanged");
}

} // namespace

std::uint32_t ReadContext::refIdOf(const Object& object) const
{
    for (const auto& [id, node] : m_file.references) {
        const auto done = m_done.find(node);
        if (done != m_done.end() && done->second.get() == &object)
            return id;
    }
    return 0;
}

Ref<SharedObject> ReadContext::object(const Node& node)
{
    DepthGuard guard(m_depth);
    if (node.type == kTypeReference) {
        const std::uint32_t id = reader(node).u32();
        const auto found = m_file.references.find(id);
        if (found == m_file.references.end())
            fail(kQ3ErrorInvalidMetafileObject,
                 "reference " + std::to_string(id) + " is in no table of contents: it refers to nothing");
        return object(*found->second);
    }
    if (const auto done = m_done.find(&node); done != m_done.end())
        return done->second;
    if (m_reading.count(&node) != 0)
        fail(kQ3ErrorInvalidMetafileObject, "a reference refers to an object that contains it (a cycle)");
    m_reading.insert(&node);
    Ref<SharedObject> result;
    try {
        result = build(node);
    } catch (...) {
        m_reading.erase(&node);
        throw;
    }
    m_reading.erase(&node);
    m_done.emplace(&node, result);
    return result;
}

Ref<SharedObject> ReadContext::build(const Node& node)
{
    if (node.type == kTypeBeginGroup) {
        // A Reference to a group (through the table of contents): the group
        // is the BeginGroup with the members that follow it in its sequence.
        std::size_t index = 0;
        const std::vector<Node>* sequence = sequenceHolding(m_file.objects, &node, index);
        if (sequence == nullptr)
            fail(kQ3ErrorInvalidMetafileObject, "a BeginGroup where a single object must be");
        return sequenceItem(*sequence, index);
    }
    if (node.type == kTypeEndGroup)
        fail(kQ3ErrorInvalidMetafileObject, "an EndGroup without its BeginGroup");
    if (node.type == kTypeContainer) {
        if (node.children.empty())
            fail(kQ3ErrorInvalidMetafileObject, "an empty container");
        const Node& root = node.children.front();
        if (root.type == kTypeContainer || root.type == kTypeReference || root.type == kTypeBeginGroup)
            fail(kQ3ErrorInvalidMetafileObject, "a container whose first object is a " +
                                                    (root.name.empty() ? typeName(root.type) : root.name));
        Parts parts{root, {}, &m_file, &node.children};
        for (std::size_t i = 1; i < node.children.size(); ++i)
            parts.subobjects.push_back(&node.children[i]);
        const ClassIO* entry = classOfType(root.type);
        if (entry == nullptr) { // the whole container: its subobjects belong to the root
            if (Ref<SharedObject> custom = customObjectFrom(*this, node, root.type))
                return custom;
            warnUnregistered(m_file, root);
            return unknownFrom(m_file, node);
        }
        Extras extras = takeExtras(*this, parts);
        Ref<SharedObject> read = entry->read(*this, parts);
        attachExtras(*read, std::move(extras));
        return read;
    }
    const ClassIO* entry = classOfType(node.type);
    if (entry == nullptr) {
        if (Ref<SharedObject> custom = customObjectFrom(*this, node, node.type))
            return custom;
        warnUnregistered(m_file, node);
        return unknownFrom(m_file, node);
    }
    return entry->read(*this, Parts{node, {}, &m_file});
}

Ref<AttributeSet> ReadContext::attributeSet(const Parts& parts)
{
    const Node* node = parts.find(kQ3SetTypeAttribute);
    if (node == nullptr)
        return {};
    return objectAs<AttributeSet>(*node, "the attribute set");
}

Ref<SharedObject> ReadContext::sequenceItem(const std::vector<Node>& nodes, std::size_t& index)
{
    DepthGuard guard(m_depth);
    const std::size_t end = itemEnd(nodes, index);
    const Node& node = nodes[index];
    if (node.type != kTypeBeginGroup) {
        index = end;
        return object(node);
    }
    if (end == nodes.size() && !groupCloses(nodes, index)) {
        index = end;
        fail(kQ3ErrorInvalidMetafile, "a BeginGroup without its EndGroup");
    }
    std::size_t first = index + 1;
    index = end;
    // A group read before (a Reference to it came first) is that one object.
    if (const auto done = m_done.find(&node); done != m_done.end())
        return done->second;
    Ref<SharedObject> opened = groupOf(node);
    Ref<Group> group = Ref<Group>::adopt(static_cast<Group*>(opened.detach()));
    first = groupStateAfter(*group, nodes, first, end - 1);
    for (std::size_t i = first; i + 1 < end;) {
        Ref<SharedObject> member = sequenceItem(nodes, i);
        if (!group->accepts(*member)) {
            errors::postWarning(kQ3WarningInvalidObjectInGroupMetafile,
                                std::string("a ") + group->classInfo().name + " cannot hold the " +
                                    member->classInfo().name + " the file puts in it; it is left out");
            continue;
        }
        group->add(std::move(member));
    }
    group->endRead();
    m_done.emplace(&node, Ref<SharedObject>(group));
    return Ref<SharedObject>(std::move(group));
}

Ref<SharedObject> ReadContext::groupOf(const Node& beginGroup)
{
    // The group object comes first: alone, in a container with its state
    // (as Q3 wrote it before), or followed by its DisplayGroupState and
    // other subobjects as siblings (as Apple's tools write it, and as the
    // MF3D parser's BeginGroup reads it: a group, then an optional state).
    const std::vector<Node>& children = beginGroup.children;
    if (children.empty())
        fail(kQ3ErrorInvalidMetafileObject, "a BeginGroup holds no group");
    const Node& first = children.front();
    if (children.size() == 1 || first.type == kTypeContainer || first.type == kTypeReference)
        return groupObject(first);
    const ClassIO* entry = classOfType(first.type);
    if (entry == nullptr) {
        // A group class an application registered (or one nobody did): the
        // group, then its state and the objects beside it.
        Ref<SharedObject> read = groupObject(first);
        for (std::size_t i = 1; i < children.size(); ++i)
            readGroupSubobject(*this, static_cast<Group&>(*read), children[i]);
        return read;
    }
    Parts parts{first, {}, &m_file, &children};
    for (std::size_t i = 1; i < children.size(); ++i)
        parts.subobjects.push_back(&children[i]);
    DepthGuard guard(m_depth);
    Extras extras = takeExtras(*this, parts);
    Ref<SharedObject> read = entry->read(*this, parts);
    attachExtras(*read, std::move(extras));
    if (!read->isType(kQ3ShapeTypeGroup))
        fail(kQ3ErrorInvalidMetafileSubObject,
             std::string("the object a BeginGroup holds is a ") + read->classInfo().name + ", no group");
    return read;
}

Ref<SharedObject> ReadContext::groupObject(const Node& node)
{
    Ref<SharedObject> read = object(node);
    if (read->isType(kQ3ShapeTypeGroup))
        return read;
    // A group of a class nobody registered (the warning said so): its
    // objects go into a display group, which keeps the unknown object and
    // writes it back.
    if (read->isType(kQ3ShapeTypeUnknown)) {
        errors::postWarning(kQ3WarningInvalidSubObjectForObject,
                            "the group's class is unknown; its objects are read into a display group, which keeps "
                            "the unknown object");
        Ref<DisplayGroup> group = makeShared<DisplayGroup>();
        group->addOtherElement(std::move(read));
        return Ref<SharedObject>(std::move(group));
    }
    fail(kQ3ErrorInvalidMetafileSubObject,
         std::string("the object a BeginGroup holds is a ") + read->classInfo().name + ", no group");
}

std::size_t ReadContext::groupStateAfter(SharedObject& group, const std::vector<Node>& nodes, std::size_t index,
                                         std::size_t end)
{
    while (index < end && nodes[index].type == kTypeDisplayGroupState) {
        applyGroupState(*this, group, nodes[index]);
        ++index;
    }
    return index;
}

bool WriteContext::hasAttributes(const AttributeSet* set)
{
    return set != nullptr && (set->nextType(kQ3AttributeTypeNone) != kQ3AttributeTypeNone ||
                              !set->otherElements().empty());
}

void WriteContext::attributeSet(const AttributeSet* set)
{
    if (hasAttributes(set))
        object(*set);
}

void WriteContext::object(const Object& object)
{
    if (m_collecting != nullptr) {
        m_collecting->submitObject(object);
        return;
    }
    DepthGuard guard(m_depth);
    std::string externalPath;
    std::uint32_t externalId = 0;
    const bool external = externalMark(object, externalPath, externalId);
    const bool isGroup = object.isType(kQ3ShapeTypeGroup);
    if (!m_stream && (!isGroup || external)) {
        if (auto found = m_written.find(&object); found != m_written.end()) {
            Written& first = found->second;
            if (first.id == 0) {
                first.id = m_nextId++;
                m_out.label(first.position, "ref" + std::to_string(first.id));
                m_labelled.push_back(&object);
            }
            m_out.begin(kTypeReference, "Reference");
            m_out.u32(first.id);
            m_out.end();
            return;
        }
    }
    if (external) {
        // Every ExternalReference the file holds is listed in its table of
        // contents with its type (the 3D Metafile Reference's condition for
        // Q3File_GetExternalReferences); later submits of the object refer
        // to this one (in a stream file each is written whole and listed).
        const Written written{m_out.position(), m_nextId++, kTypeExternalReference, "ExternalReference"};
        m_out.label(written.position, "ref" + std::to_string(written.id));
        writeExternalReference(m_out, externalPath, externalId);
        if (m_stream) {
            m_streamExternals.push_back(written);
        } else {
            m_written[&object] = written;
            m_added.push_back(&object);
            m_keep.push_back(Ref<SharedObject>::retain(
                const_cast<SharedObject*>(static_cast<const SharedObject*>(&object))));
        }
        return;
    }
    // A class an application registered writes itself through its methods.
    const ClassIO* entry = classOfObject(object);
    const CustomClass* custom = customWriterOf(object);
    const ClassIO customEntry{custom ? custom->type() : 0, custom ? custom->name().c_str() : "", nullptr,
                              writeCustomObject};
    // A group class writes as its parent group, under its own name (GroupIO).
    if (custom != nullptr && !isGroup)
        entry = &customEntry;
    if (entry == nullptr) {
        errors::postWarning(kQ3WarningNoObjectSupportForWriteMethod,
                            std::string("Q3 has no 3DMF form for a ") + object.classInfo().name +
                                (customInstanceOf(const_cast<Object&>(object)) != nullptr
                                     ? " (its class has no traverse method, kQ3XMethodTypeObjectTraverse)"
                                     : "") +
                                "; it is left out of the file");
        return;
    }
    const bool remember = !m_stream && !isGroup && object.isType(kQ3ObjectTypeShared);
    if (remember) {
        Written& written = m_written[&object] = Written{m_out.position(), 0, entry->type, entry->name};
        if (m_database) {
            written.id = m_nextId++;
            m_out.label(written.position, "ref" + std::to_string(written.id));
        }
        m_added.push_back(&object);
        m_keep.push_back(Ref<SharedObject>::retain(
            const_cast<SharedObject*>(static_cast<const SharedObject*>(&object))));
    }
    const std::size_t start = m_out.position();
    if (m_depth > 1) {
        entry->write(*this, object);
        if (remember && m_out.position() == start) // a traverse method chose to write nothing
            m_written.erase(&object);
        ownElements(object, start);
        return;
    }
    // A submitted object is written whole or not at all: a failure inside
    // (a group nested past the limit) leaves the file as it was.
    const Encoder::Mark before = m_out.mark();
    const std::size_t kept = m_keep.size() - (remember ? 1 : 0);
    const std::uint32_t nextId = m_nextId;
    const std::size_t streamExternals = m_streamExternals.size();
    m_added.assign(remember ? 1 : 0, &object);
    m_labelled.clear();
    try {
        entry->write(*this, object);
        if (remember && m_out.position() == start) // a traverse method chose to write nothing
            m_written.erase(&object);
        ownElements(object, start);
    } catch (...) {
        m_out.rollback(before);
        for (const Object* added : m_added)
            m_written.erase(added);
        for (const Object* labelled : m_labelled)
            if (auto found = m_written.find(labelled); found != m_written.end())
                found->second.id = 0;
        m_keep.resize(kept);
        m_nextId = nextId;
        m_streamExternals.resize(streamExternals);
        throw;
    }
}

void WriteContext::ownElements(const Object& object, std::size_t start)
{
    const ObjectElements* elements = object.elementsIfAny();
    if (elements == nullptr || !hasFileElements(elements->own.get()) || object.isType(kQ3SharedTypeSet) ||
        object.isType(kQ3ShapeTypeGroup) || m_out.position() == start)
        return;
    const std::size_t moved = m_out.reopenAsContainer(start);
    if (moved != 0) {
        for (auto& [written, at] : m_written)
            if (at.position > start)
                at.position += moved;
        for (Written& external : m_streamExternals)
            if (external.position > start)
                external.position += moved;
    }
    writeCustomElements(*this, *elements->own);
    m_out.end();
}

void WriteContext::temporary(const Object& object)
{
    if (m_collecting != nullptr) {
        m_collecting->submitTemporary(object);
        return;
    }
    const ClassIO* entry = classOfObject(object);
    if (entry == nullptr) {
        errors::postWarning(kQ3WarningNoObjectSupportForWriteMethod,
                            std::string("Q3 has no 3DMF form for a ") + object.classInfo().name);
        return;
    }
    entry->write(*this, object);
}

std::vector<unsigned char> WriteContext::finish(TQ3FileMode mode)
{
    std::vector<Encoder::TocEntry> toc;
    for (const auto& [object, written] : m_written)
        if (written.id != 0)
            toc.push_back({written.id, written.position, written.type, written.name});
    for (const Written& written : m_streamExternals)
        toc.push_back({written.id, written.position, written.type, written.name});
    std::sort(toc.begin(), toc.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    return m_out.finish(mode, toc);
}

} // namespace q3::io
