// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/File.h"

#include "core/ErrorManager.h"
#include "geometry/Geometry.h"
#include "group/Group.h"
#include "io/CustomIO.h"
#include "io/ExternalReference.h"
#include "io/StringObject.h"
#include "shader/Shader.h"
#include "style/Style.h"
#include "view/Transform.h"

#include <filesystem>

namespace q3 {

const ClassInfo kFileClass{kQ3SharedTypeFile, &kSharedClass, "file"};
const ClassInfo kEndGroupClass{kQ3SharedTypeEndGroup, &kSharedClass, "end of group"};

namespace {

/// The writing loop's target: retained objects through write(), immediate
/// mode shapes through the ShapeVisitor calls.
class FileWriteTarget final : public WriteTarget {
public:
    FileWriteTarget(std::shared_ptr<io::WriteContext> context, std::shared_ptr<File::Idle> idle,
                    TQ3ViewObject view)
        : m_context(std::move(context)), m_idle(std::move(idle)), m_view(view)
    {
    }

    void write(const Object& object) override
    {
        if (proceed()) {
            m_context->setView(m_view);
            m_context->object(object);
        }
    }
    void visitGeometry(const Geometry& geometry) override { temporary(geometry); }
    void visitAttributeSet(const AttributeSet& attributes) override { temporary(attributes); }
    void visitStyle(const Style& style) override { temporary(style); }
    void visitShader(const Shader& shader) override { temporary(shader); }
    void visitTransform(const Transform& transform) override { temporary(transform); }
    void pushState() override {}
    void popState() override {}
    bool beginGroup(const DisplayGroup&) override { return false; }
    void endGroup(const DisplayGroup&) override {}
    bool cancelled() const override { return m_cancelled; }

private:
    // The idle method runs before each object; once it asks to cancel,
    // nothing more is written in this loop.
    bool proceed()
    {
        if (!m_cancelled && !m_idle->proceed())
            m_cancelled = true;
        return !m_cancelled;
    }
    void temporary(const Object& object)
    {
        if (proceed()) {
            m_context->setView(m_view);
            m_context->temporary(object);
        }
    }

    std::shared_ptr<io::WriteContext> m_context;
    std::shared_ptr<File::Idle> m_idle;
    TQ3ViewObject m_view;
    bool m_cancelled = false;
};

} // namespace

File::~File()
{
    m_idle->method = nullptr; // a writing loop may outlive the file
    if (m_writer)
        m_writer->setFile(nullptr);
    io::forgetExternals(this);
    release();
}

Object* File::duplicate() const
{
    fail(kQ3ErrorInvalidObjectType, "a file object cannot be duplicated");
}

void File::setStorage(Ref<Storage> storage)
{
    if (isOpen())
        fail(kQ3ErrorFileIsOpen, "the file is open");
    m_storage = std::move(storage);
}

TQ3FileMode File::openRead()
{
    if (isOpen())
        fail(kQ3ErrorFileAlreadyOpen, "the file is already open");
    if (!m_storage)
        fail(kQ3ErrorNoStorageSetForFile, "the file has no storage (Q3File_SetStorage)");
    const std::size_t size = m_storage->size();
    if (size > limits::kMaxStorageBytes)
        fail(kQ3ErrorInvalidMetafile, "the storage holds " + std::to_string(size) + " bytes, more than Q3 reads");
    auto parsed = io::parse(m_storage->readAll(), &io::typeOfName);
    m_mode = parsed->mode | (parsed->encoding == io::Encoding::kText           ? kQ3FileModeText
                             : parsed->encoding == io::Encoding::kBinaryLittle ? kQ3FileModeSwap
                                                                               : 0);
    m_file = std::move(parsed);
    m_reader = std::make_unique<io::ReadContext>(*m_file);
    m_reader->setFileObject(this);
    if (const auto* path = dynamic_cast<const UnixPathStorage*>(m_storage.get()))
        m_reader->setBaseDirectory(std::filesystem::path(path->path()).parent_path().string());
    m_next = 0;
    m_state = State::kReading;
    m_storage->acquire();
    return m_mode;
}

void File::openWrite(TQ3FileMode mode)
{
    if (isOpen())
        fail(kQ3ErrorFileAlreadyOpen, "the file is already open");
    if (!m_storage)
        fail(kQ3ErrorNoStorageSetForFile, "the file has no storage (Q3File_SetStorage)");
    const TQ3FileMode known = kQ3FileModeStream | kQ3FileModeDatabase | kQ3FileModeText | kQ3FileModeSwap;
    if ((mode & ~known) != 0 || ((mode & kQ3FileModeStream) && (mode & kQ3FileModeDatabase)) ||
        ((mode & kQ3FileModeText) && (mode & kQ3FileModeSwap)))
        fail(kQ3ErrorInvalidParameter, "mode " + std::to_string(mode) +
                                           " is not Normal, Stream or Database, with Text, Swap or neither");
    const io::Encoding encoding = (mode & kQ3FileModeText)   ? io::Encoding::kText
                                  : (mode & kQ3FileModeSwap) ? io::Encoding::kBinaryLittle
                                                             : io::Encoding::kBinaryBig;
    m_writer = std::make_shared<io::WriteContext>(encoding, (mode & kQ3FileModeStream) != 0,
                                                  (mode & kQ3FileModeDatabase) != 0);
    m_writer->setFile(this);
    m_mode = mode;
    m_state = State::kWriting;
    m_storage->acquire();
}

TQ3FileMode File::mode() const
{
    if (!isOpen())
        fail(kQ3ErrorFileNotOpen, "the file is not open");
    return m_mode;
}

TQ3FileVersion File::version() const
{
    if (!isOpen())
        fail(kQ3ErrorFileNotOpen, "the file is not open");
    if (m_state == State::kWriting)
        return kQ3FileVersionCurrent;
    return Q3FileVersion(m_file->major, m_file->minor);
}

void File::release()
{
    if (m_writer)
        m_writer->setFile(nullptr); // a writing loop may go on after the close
    if (m_state != State::kClosed && m_storage)
        m_storage->releaseUse();
    m_state = State::kClosed;
    m_openGroups = 0;
    m_data.reset();
    m_reader.reset();
    m_file.reset();
    m_writer.reset();
}

void File::close()
{
    if (!isOpen())
        fail(kQ3ErrorFileNotOpen, "the file is not open");
    if (m_methods > 0 || (m_writer && m_writer->busy()))
        fail(kQ3ErrorAccessRestricted, "a custom class's method is reading or writing the file");
    if (m_state == State::kWriting) {
        std::shared_ptr<io::WriteContext> writer = m_writer;
        Ref<Storage> storage = m_storage;
        const TQ3FileMode mode = m_mode & (kQ3FileModeStream | kQ3FileModeDatabase);
        release();
        storage->replaceAll(writer->finish(mode));
        return;
    }
    release();
}

void File::cancel()
{
    if (!isOpen())
        fail(kQ3ErrorFileNotOpen, "the file is not open");
    if (m_methods > 0 || (m_writer && m_writer->busy()))
        fail(kQ3ErrorAccessRestricted, "a custom class's method is reading or writing the file");
    release();
}

void File::requireReading() const
{
    if (m_state != State::kReading)
        fail(kQ3ErrorFileNotOpen, "the file is not open for reading");
}

bool File::isEndOfFile() const
{
    if (m_state != State::kReading)
        return true;
    if (m_data && m_data->scoped)
        return !m_data->childrenLeft();
    return !(m_data && m_data->childrenLeft()) && m_next >= m_file->objects.size();
}

TQ3ObjectType File::nextObjectType() const
{
    requireReading();
    if (isEndOfFile())
        return kQ3ObjectTypeInvalid;
    if (m_data && m_data->childrenLeft())
        return typeOfNode(m_data->container->children[m_data->nextChild]);
    return typeOfNode(m_file->objects[m_next]);
}

TQ3ObjectType File::typeOfNode(const io::Node& first) const
{
    const io::Node* node = &first;
    for (int hops = 0; hops < 4; ++hops) {
        if (node->type == io::kTypeEndGroup)
            return kQ3SharedTypeEndGroup;
        if (node->type == io::kTypeReference) {
            io::DataReader reader(*m_file, *node);
            if (reader.atEnd())
                break;
            const std::uint32_t id = reader.u32();
            const auto found = m_file->references.find(id);
            if (found == m_file->references.end())
                break;
            node = found->second;
        } else if ((node->type == io::kTypeContainer || node->type == io::kTypeBeginGroup) &&
                   !node->children.empty()) {
            node = &node->children.front();
        } else {
            break;
        }
    }
    return io::classOfType(node->type) != nullptr || (node->type != 0 && findCustomClass(node->type))
               ? node->type
               : kQ3ShapeTypeUnknown;
}

bool File::isNextObjectOfType(TQ3ObjectType type) const
{
    const TQ3ObjectType next = nextObjectType();
    if (next == type)
        return true;
    const ClassInfo* info = findClass(next);
    return info != nullptr && info->isA(type);
}

void File::idleBeforeReading() const
{
    if (!m_idle->proceed())
        fail(kQ3ErrorFileCancelled, "the idle method returned kQ3Failure: reading is cancelled");
}

Ref<SharedObject> File::readObject()
{
    requireReading();
    if (isEndOfFile())
        fail(kQ3ErrorEndOfFile, "no object is left in the file");
    idleBeforeReading();
    if (m_data && m_data->childrenLeft()) {
        // A subobject of the container primitive reads started on.
        std::size_t index = m_data->nextChild;
        try {
            if (Ref<SharedObject> set = io::readElementAsSet(*m_reader, m_data->container->children[index])) {
                m_data->nextChild = index + 1;
                return set;
            }
            Ref<SharedObject> object = m_reader->sequenceItem(m_data->container->children, index);
            m_data->nextChild = index;
            return object;
        } catch (...) {
            m_data->nextChild = std::max(index, m_data->nextChild + 1);
            throw;
        }
    }
    m_data.reset();
    const io::Node& node = m_file->objects[m_next];
    if (node.type == io::kTypeEndGroup && m_openGroups > 0) {
        ++m_next;
        --m_openGroups;
        return Ref<SharedObject>(makeShared<EndGroup>());
    }
    if (node.type == io::kTypeBeginGroup && m_readGroup == kQ3FileReadObjectsInGroup) {
        ++m_next; // a failure leaves the group's objects to be read one by one
        Ref<SharedObject> group = m_reader->groupOf(node);
        m_next = m_reader->groupStateAfter(*group, m_file->objects, m_next, m_file->objects.size());
        ++m_openGroups;
        return group;
    }
    // On failure the item is skipped, so the next call reads the one after.
    std::size_t index = m_next;
    try {
        if (Ref<SharedObject> set = io::readElementAsSet(*m_reader, node)) {
            m_next = index + 1;
            return set;
        }
        Ref<SharedObject> object = m_reader->sequenceItem(m_file->objects, index);
        m_next = index;
        return object;
    } catch (...) {
        m_next = std::max(index, m_next + 1);
        throw;
    }
}

void File::skipObject()
{
    requireReading();
    if (isEndOfFile())
        fail(kQ3ErrorEndOfFile, "no object is left in the file");
    idleBeforeReading();
    if (m_data && m_data->childrenLeft()) {
        ++m_data->nextChild;
        return;
    }
    m_data.reset();
    std::size_t open = 0;
    std::size_t i = m_next;
    do {
        const TQ3ObjectType type = m_file->objects[i].type;
        if (type == io::kTypeBeginGroup)
            ++open;
        else if (type == io::kTypeEndGroup && open > 0)
            --open;
        ++i;
    } while (open > 0 && i < m_file->objects.size());
    m_next = i;
}

void File::setReadInGroup(TQ3FileReadGroupState state)
{
    if (state != kQ3FileReadWholeGroup && state != kQ3FileReadObjectsInGroup)
        fail(kQ3ErrorInvalidParameter, "readGroupState " + std::to_string(state) +
                                           " is neither kQ3FileReadWholeGroup nor kQ3FileReadObjectsInGroup");
    m_readGroup = state;
}

TQ3FileReadGroupState File::readInGroup() const
{
    return m_readGroup | (m_openGroups > 0 ? kQ3FileCurrentlyInsideGroup : 0);
}

std::shared_ptr<WriteTarget> File::writeTarget(TQ3ViewObject view)
{
    if (m_state != State::kWriting)
        fail(kQ3ErrorFileNotOpen, "the file is not open for writing");
    return std::make_shared<FileWriteTarget>(m_writer, m_idle, view);
}

namespace {

// The node whose data primitive reads read for an object of the file: the
// object itself, a container's root; null for what has no data of its own.
const io::Node* dataNodeOf(const io::Node& node)
{
    if (node.type == io::kTypeBeginGroup || node.type == io::kTypeEndGroup || node.type == io::kTypeReference ||
        node.type == io::kTypeTableOfContents)
        return nullptr;
    if (node.type != io::kTypeContainer)
        return &node;
    if (node.children.empty())
        return nullptr;
    const io::Node& root = node.children.front();
    return root.type == io::kTypeContainer ? nullptr : dataNodeOf(root);
}

} // namespace

std::size_t File::readNode(const io::Node& node, const std::function<void()>& body)
{
    requireReading();
    const io::Node* data = dataNodeOf(node);
    if (data == nullptr)
        fail(kQ3ErrorInvalidMetafileObject, "the object (" + (node.name.empty() ? io::typeName(node.type) : node.name) +
                                                ") has no data of its own to read");
    auto state = std::make_unique<DataState>();
    state->container = node.type == io::kTypeContainer ? &node : nullptr;
    state->reader = std::make_unique<io::DataReader>(*m_file, *data);
    state->scoped = true;
    std::swap(state, m_data);
    ++m_methods;
    struct Restore {
        File& file;
        std::unique_ptr<DataState>& saved;
        ~Restore()
        {
            --file.m_methods;
            std::swap(saved, file.m_data);
        }
    } restore{*this, state};
    body();
    return m_data->container != nullptr ? m_data->nextChild : 0;
}

io::DataReader& File::dataReader()
{
    if (m_state != State::kReading)
        fail(kQ3ErrorReadStateInactive, "the file is not open for reading");
    if (m_data && m_data->reader)
        return *m_data->reader;
    if (m_next >= m_file->objects.size())
        fail(kQ3ErrorEndOfFile, "no object is left in the file to read data from");
    const io::Node& node = m_file->objects[m_next];
    const io::Node* data = dataNodeOf(node);
    if (data == nullptr)
        fail(kQ3ErrorInvalidMetafileObject, "the next object (" + (node.name.empty() ? io::typeName(node.type) : node.name) +
                                                ") has no data of its own to read");
    auto state = std::make_unique<DataState>();
    state->container = node.type == io::kTypeContainer ? &node : nullptr;
    state->reader = std::make_unique<io::DataReader>(*m_file, *data);
    m_data = std::move(state);
    ++m_next;
    return *m_data->reader;
}

void File::dataEnds(const char* what) const
{
    fail(kQ3ErrorReadMoreThanSize, std::string("the object's data end before ") + what + " (" +
                                       std::to_string(m_data->reader->remaining()) +
                                       (m_file->encoding == io::Encoding::kText ? " tokens" : " bytes") + " left)");
}

bool File::isEndOfData() const
{
    if (m_state != State::kReading)
        return true;
    if (m_data && m_data->reader)
        return m_data->reader->atEnd();
    if (m_next >= m_file->objects.size())
        return true;
    const io::Node* data = dataNodeOf(m_file->objects[m_next]);
    return data == nullptr || io::DataReader(*m_file, *data).atEnd();
}

bool File::isEndOfContainer() const
{
    return m_state != State::kReading || !(m_data && m_data->childrenLeft());
}

io::Encoder& File::dataWriter()
{
    if (m_state != State::kWriting)
        fail(kQ3ErrorWriteStateInactive, "the file is not open for writing");
    return m_writer->out();
}

void File::markAsExternalReference(const SharedObject& object)
{
    requireReading();
    const auto* path = dynamic_cast<const UnixPathStorage*>(m_storage.get());
    if (path == nullptr)
        fail(kQ3ErrorInvalidParameter, "an external reference names its file by path: the file's storage is not a "
                                       "Unix path storage");
    const std::uint32_t refId = m_reader->refIdOf(object);
    if (refId == 0)
        fail(kQ3ErrorInvalidParameter, std::string("the ") + object.classInfo().name +
                                           " was not read from this file as an object its table of contents "
                                           "lists, so no external reference can name it");
    io::markExternal(object, path->path(), refId, this);
}

Ref<SharedObject> File::externalReferences() const
{
    requireReading();
    const std::vector<std::string> paths = io::externalReferencePaths(*m_file);
    if (paths.empty())
        return {};
    Ref<Group> group = makeShared<Group>();
    for (const std::string& path : paths)
        group->add(Ref<SharedObject>(makeShared<CString>(path)));
    return Ref<SharedObject>(std::move(group));
}

void File::setIdleMethod(TQ3FileIdleMethod method, const void* data)
{
    m_idle->method = method;
    m_idle->data = data;
    m_idle->file = this;
}

} // namespace q3
