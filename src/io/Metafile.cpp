// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "io/Metafile.h"

#include "core/Error.h"
#include "core/ErrorManager.h"
#include "core/Limits.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>

namespace q3::io {

std::string typeName(TQ3ObjectType type)
{
    std::string name = "'";
    for (int shift = 24; shift >= 0; shift -= 8) {
        const char c = static_cast<char>((static_cast<std::uint32_t>(type) >> shift) & 0xFF);
        name += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    }
    return name + "'";
}

namespace {

bool sameName(const std::string& a, const char* b)
{
    const std::size_t n = std::strlen(b);
    if (a.size() != n)
        return false;
    for (std::size_t i = 0; i < n; ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

[[noreturn]] void invalid(const std::string& why)
{
    fail(kQ3ErrorInvalidMetafile, why);
}

// ---- binary ----------------------------------------------------------------

class BinaryParser {
public:
    BinaryParser(Metafile& file) : m_file(file), m_little(file.encoding == Encoding::kBinaryLittle) {}

    std::uint32_t u32At(std::size_t at) const
    {
        const unsigned char* p = m_file.bytes.data() + at;
        return m_little ? (std::uint32_t{p[3]} << 24 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[1]} << 8 | p[0])
                        : (std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3]);
    }

    void parseSequence(std::size_t begin, std::size_t end, std::size_t depth, std::vector<Node>& out)
    {
        if (depth > limits::kMaxMetafileNesting)
            invalid("containers nest deeper than " + std::to_string(limits::kMaxMetafileNesting) + " levels");
        std::size_t at = begin;
        while (at < end) {
            if (depth == 0 && isTrailingJunk(at, end)) {
                // Some shipped files carry padding or junk after their last
                // object; QuickDraw 3D read the objects before it.
                errors::postWarning(kQ3WarningInvalidMetafileObject,
                                    "the " + std::to_string(end - at) + " bytes after the last object (from byte " +
                                        std::to_string(at) + ") are no object; they are ignored");
                return;
            }
            if (end - at < 8)
                invalid("the object at byte " + std::to_string(at) + " is truncated: " +
                        std::to_string(end - at) + " bytes left, a type and a size need 8");
            Node node;
            node.type = static_cast<TQ3ObjectType>(u32At(at));
            const std::uint32_t size = u32At(at + 4);
            if (size > end - at - 8)
                invalid("the size " + std::to_string(size) + " of the " + typeName(node.type) +
                        " object at byte " + std::to_string(at) + " overruns its container (" +
                        std::to_string(end - at - 8) + " bytes left)");
            node.offset = at;
            node.dataBegin = at + 8;
            node.dataEnd = at + 8 + size;
            if (node.type == kTypeContainer || node.type == kTypeBeginGroup)
                parseSequence(node.dataBegin, node.dataEnd, depth + 1, node.children);
            out.push_back(std::move(node));
            at += 8 + std::size_t{size};
        }
    }

private:
    // Whether the bytes from `at` to the end of the file cannot be an
    // object and are left over: fewer than an object's type and size, all
    // zero (padding), or a type that is not four printable characters whose
    // size overruns the file. An object whose type reads as a type and
    // whose size overruns is a truncated file, which stays an error.
    bool isTrailingJunk(std::size_t at, std::size_t end) const
    {
        if (end - at < 8)
            return true;
        const unsigned char* p = m_file.bytes.data();
        if (std::all_of(p + at, p + end, [](unsigned char b) { return b == 0; }))
            return true;
        const bool printable = std::all_of(p + at, p + at + 4, [](unsigned char b) { return b >= 0x20 && b < 0x7F; });
        return !printable && u32At(at + 4) > end - at - 8;
    }

    Metafile& m_file;
    bool m_little;
};

// ---- text ------------------------------------------------------------------

struct Token {
    std::string text;
    std::size_t line;
    std::size_t begin; // byte offsets in the file
};

std::vector<Token> tokenize(const std::vector<unsigned char>& bytes)
{
    std::vector<Token> tokens;
    std::size_t line = 1;
    std::size_t i = 0;
    const std::size_t n = bytes.size();
    while (i < n) {
        const char c = static_cast<char>(bytes[i]);
        if (c == '\n' || c == '\r') {
            // A line ends at LF, CR (Mac text files) or CR LF.
            ++line;
            i += (c == '\r' && i + 1 < n && bytes[i + 1] == '\n') ? 2 : 1;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (c == '#') {
            while (i < n && bytes[i] != '\n' && bytes[i] != '\r')
                ++i;
        } else if (c == '(' || c == ')' || c == '|') {
            tokens.push_back({std::string(1, c), line, i});
            ++i;
        } else if (c == '"') {
            std::string text = "\"";
            const std::size_t begin = i;
            ++i;
            while (i < n && bytes[i] != '"') {
                if (bytes[i] == '\\' && i + 1 < n)
                    ++i;
                if (bytes[i] == '\n' || (bytes[i] == '\r' && (i + 1 >= n || bytes[i + 1] != '\n')))
                    ++line;
                text += static_cast<char>(bytes[i]);
                ++i;
            }
            if (i >= n)
                fail(kQ3ErrorInvalidMetafilePrimitive, "line " + std::to_string(line) + ": a string is not closed");
            ++i;
            tokens.push_back({text + "\"", line, begin});
        } else {
            std::string text;
            const std::size_t begin = i;
            while (i < n && !std::isspace(bytes[i]) && bytes[i] != '(' && bytes[i] != ')' && bytes[i] != '|' &&
                   bytes[i] != '#' && bytes[i] != '"')
                text += static_cast<char>(bytes[i++]);
            tokens.push_back({text, line, begin});
        }
    }
    return tokens;
}

bool isName(const std::string& token)
{
    return (!token.empty() && std::isalpha(static_cast<unsigned char>(token[0]))) || sameName(token, "3DMetafile");
}

// A boolean written as a word where a number is stored (TQ3Boolean fields,
// flags): True and False in any case, as Apple's and other tools wrote
// them.
bool booleanWord(const std::string& token, std::uint32_t& value)
{
    if (sameName(token, "True")) {
        value = 1;
        return true;
    }
    if (sameName(token, "False")) {
        value = 0;
        return true;
    }
    return false;
}

class TextParser {
public:
    TextParser(std::vector<Token> tokens, NameLookup names) : m_tokens(std::move(tokens)), m_names(names) {}

    bool done() const { return m_at >= m_tokens.size(); }
    /// Whether the rest of the file is left over after the last object:
    /// the next token cannot start an object (a label, or a name followed by
    /// '(') and no parenthesis follows (stray words, control bytes).
    /// Anything with parentheses is a malformed object, not junk.
    bool atLeftOver() const
    {
        if (done())
            return false;
        const std::string& token = m_tokens[m_at].text;
        if (token.size() > 1 && token.back() == ':')
            return false;
        if (isName(token) && m_at + 1 < m_tokens.size() && m_tokens[m_at + 1].text == "(")
            return false;
        return std::none_of(m_tokens.begin() + static_cast<std::ptrdiff_t>(m_at), m_tokens.end(),
                            [](const Token& t) { return t.text == "(" || t.text == ")"; });
    }
    std::size_t leftOverLine() const { return m_tokens[m_at].line; }

    // Parses `[label:] Name ( ... )` at the current token.
    Node object(std::size_t depth)
    {
        if (depth > limits::kMaxMetafileNesting)
            invalid("objects nest deeper than " + std::to_string(limits::kMaxMetafileNesting) + " levels");
        Node node;
        std::string first = next("an object");
        if (first.size() > 1 && first.back() == ':') {
            node.label = first.substr(0, first.size() - 1);
            first = next("an object after the label " + node.label);
        }
        if (!isName(first))
            fail(kQ3ErrorInvalidMetafilePrimitive,
                 "line " + std::to_string(line()) + ": expected an object name, found '" + first + "'");
        for (std::size_t more = spacedName(m_at - 1); more > 1; --more)
            first += " " + m_tokens[m_at++].text;
        node.name = first;
        node.type = lookup(first);
        node.offset = line();
        if (next("'('") != "(")
            fail(kQ3ErrorInvalidMetafilePrimitive,
                 "line " + std::to_string(line()) + ": expected '(' after " + first);
        node.dataBegin = m_tokens[m_at - 1].begin + 1;
        for (;;) {
            if (done())
                invalid("the file ends inside " + first + " (a ')' is missing)");
            const std::string& token = m_tokens[m_at].text;
            if (token == ")") {
                node.dataEnd = m_tokens[m_at].begin;
                ++m_at;
                break;
            }
            const bool labelled = token.size() > 1 && token.back() == ':';
            const bool named = isName(token) && ((m_at + 1 < m_tokens.size() && m_tokens[m_at + 1].text == "(") ||
                                                 spacedName(m_at) > 1);
            if (labelled || named)
                node.children.push_back(object(depth + 1));
            else {
                if (token == "(")
                    fail(kQ3ErrorInvalidMetafilePrimitive,
                         "line " + std::to_string(line()) + ": '(' without an object name");
                node.tokens.push_back(token);
                ++m_at;
            }
        }
        return node;
    }

private:
    // The class names of registered classes may hold spaces ("Apple
    // Computer, Inc.:NameElement"), which split them into several tokens:
    // how many tokens from `at` make such a name followed by '(', or 0.
    std::size_t spacedName(std::size_t at) const
    {
        std::string joined = m_tokens[at].text;
        for (std::size_t end = at + 1; end < m_tokens.size() && end < at + 8; ++end) {
            const std::string& token = m_tokens[end].text;
            if (token == "(")
                return end - at > 1 && m_names(joined) != 0 ? end - at : 0;
            if (token == ")" || token == "|" || token.front() == '"')
                return 0;
            joined += " " + token;
        }
        return 0;
    }

    TQ3ObjectType lookup(const std::string& name) const
    {
        if (sameName(name, "Container"))
            return kTypeContainer;
        if (sameName(name, "BeginGroup"))
            return kTypeBeginGroup;
        if (sameName(name, "EndGroup"))
            return kTypeEndGroup;
        if (sameName(name, "Reference"))
            return kTypeReference;
        if (sameName(name, "TableOfContents"))
            return kTypeTableOfContents;
        if (sameName(name, "3DMetafile"))
            return kTypeHeader;
        return m_names(name);
    }
    std::size_t line() const { return m_tokens[std::min(m_at, m_tokens.size() - 1)].line; }
    std::string next(const std::string& what)
    {
        if (done())
            invalid("the file ends where " + what + " should be");
        return m_tokens[m_at++].text;
    }

    std::vector<Token> m_tokens;
    NameLookup m_names;
    std::size_t m_at = 0;
};

std::uint32_t parseUnsigned(const std::string& token, std::uint64_t max)
{
    if (std::uint32_t truth; booleanWord(token, truth))
        return truth;
    if (token.empty() || token[0] == '-' || token[0] == '+')
        fail(kQ3ErrorInvalidMetafilePrimitive, "'" + token + "' is not an unsigned integer");
    errno = 0;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(token.c_str(), &end, 0);
    if (errno != 0 || end == token.c_str() || *end != '\0' || value > max)
        fail(kQ3ErrorInvalidMetafilePrimitive, "'" + token + "' is not an unsigned integer in range");
    return static_cast<std::uint32_t>(value);
}

std::uint64_t parseUnsigned64(const std::string& token)
{
    if (token.empty() || token[0] == '-' || token[0] == '+')
        fail(kQ3ErrorInvalidMetafilePrimitive, "'" + token + "' is not an unsigned integer");
    errno = 0;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(token.c_str(), &end, 0);
    if (errno != 0 || end == token.c_str() || *end != '\0')
        fail(kQ3ErrorInvalidMetafilePrimitive, "'" + token + "' is not a 64-bit unsigned integer");
    return value;
}

std::int64_t parseSigned(const std::string& token, std::int64_t min, std::int64_t max)
{
    if (std::uint32_t truth; booleanWord(token, truth))
        return truth;
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(token.c_str(), &end, 0);
    if (errno != 0 || end == token.c_str() || *end != '\0' || value < min || value > max)
        fail(kQ3ErrorInvalidMetafilePrimitive,
             "'" + token + "' is not an integer from " + std::to_string(min) + " to " + std::to_string(max));
    return value;
}

const Node* findLabel(const std::vector<Node>& nodes, const std::string& label)
{
    for (const Node& node : nodes) {
        if (node.label == label)
            return &node;
        if (const Node* inside = findLabel(node.children, label))
            return inside;
    }
    return nullptr;
}

const Node* findOffset(const std::vector<Node>& nodes, std::size_t offset)
{
    for (const Node& node : nodes) {
        if (node.offset == offset)
            return &node;
        if (offset > node.offset && offset < node.dataEnd)
            if (const Node* inside = findOffset(node.children, offset))
                return inside;
    }
    return nullptr;
}

// Gives the nodes of a file-local type (a negative type a Type object
// names) that name, and the type of the class of that name when one has it.
void resolveTypes(std::vector<Node>& nodes, const std::map<TQ3ObjectType, std::string>& declared, NameLookup names)
{
    for (Node& node : nodes) {
        const auto found = declared.find(node.type);
        if (found != declared.end()) {
            node.name = found->second;
            if (const TQ3ObjectType resolved = names(found->second))
                node.type = resolved;
        }
        resolveTypes(node.children, declared, names);
    }
}

void parseBinary(Metafile& file, NameLookup names)
{
    BinaryParser parser(file);
    const std::size_t size = file.bytes.size();
    if (size < 24)
        invalid("the file is too short for a 3DMF header (" + std::to_string(size) + " bytes)");
    if (parser.u32At(4) != 16)
        invalid("the 3DMF header's size is " + std::to_string(parser.u32At(4)) + ", not 16");
    const std::uint32_t version = parser.u32At(8);
    file.major = file.encoding == Encoding::kBinaryLittle ? version & 0xFFFF : version >> 16;
    file.minor = file.encoding == Encoding::kBinaryLittle ? version >> 16 : version & 0xFFFF;
    file.mode = parser.u32At(12);
    const std::uint64_t tocOffset = file.encoding == Encoding::kBinaryLittle
                                        ? (std::uint64_t{parser.u32At(20)} << 32 | parser.u32At(16))
                                        : (std::uint64_t{parser.u32At(16)} << 32 | parser.u32At(20));
    std::vector<Node> all;
    parser.parseSequence(24, size, 0, all);
    const Node* toc = nullptr;
    std::map<TQ3ObjectType, std::string> declared;
    for (Node& node : all)
        if (node.type == kTypeType) {
            // Type ( -1 "Apple Computer, Inc.:NameElement" ): what a custom
            // type stands for in this file.
            DataReader in(file, node);
            const std::int32_t id = in.i32();
            std::string name = in.string();
            if (id >= 0)
                fail(kQ3ErrorInvalidMetafileObject, "a Type object declares the type " + std::to_string(id) +
                                                        ", not a negative one");
            declared[static_cast<TQ3ObjectType>(static_cast<std::uint32_t>(id))] = std::move(name);
        } else if (node.type != kTypeTableOfContents)
            file.objects.push_back(std::move(node));
        else if (node.offset == tocOffset)
            toc = &node;
    if (!declared.empty())
        resolveTypes(file.objects, declared, names);
    if (tocOffset != 0 && toc == nullptr)
        invalid("the header's table of contents offset " + std::to_string(tocOffset) + " is no table of contents");
    if (toc == nullptr)
        return;
    DataReader reader(file, *toc);
    reader.u64(); // the next table of contents: Q3 reads one
    reader.u32(); // reference seed
    reader.i32(); // type seed
    const std::uint32_t entryType = reader.u32();
    reader.u32(); // entry size
    if (entryType > 1)
        fail(kQ3ErrorInvalidMetafileObject, "the table of contents' entry type is " + std::to_string(entryType));
    const std::uint32_t entries = reader.count(entryType == 1 ? 16 : 12, entryType == 1 ? 3 : 2, "table of contents entries");
    for (std::uint32_t i = 0; i < entries; ++i) {
        const std::uint32_t id = reader.u32();
        const std::uint64_t location = reader.u64();
        if (entryType == 1)
            reader.u32();
        const Node* target = findOffset(file.objects, static_cast<std::size_t>(location));
        if (target == nullptr)
            fail(kQ3ErrorInvalidMetafileLabel, "table of contents entry " + std::to_string(id) +
                                                   " points at byte " + std::to_string(location) +
                                                   ", where no object starts");
        file.references[id] = target;
    }
}

void parseText(Metafile& file, NameLookup names)
{
    TextParser parser(tokenize(file.bytes), names);
    if (parser.done())
        invalid("the file is empty");
    Node header = parser.object(0);
    if (header.type != kTypeHeader)
        invalid("a text 3DMF file starts with 3DMetafile, not " + header.name);
    if (header.tokens.size() < 3)
        invalid("the 3DMetafile header needs a version and a mode");
    file.major = parseUnsigned(header.tokens[0], 0xFFFF);
    file.minor = parseUnsigned(header.tokens[1], 0xFFFF);
    const std::string& mode = header.tokens[2];
    if (sameName(mode, "Normal"))
        file.mode = kQ3FileModeNormal;
    else if (sameName(mode, "Stream"))
        file.mode = kQ3FileModeStream;
    else if (sameName(mode, "Database"))
        file.mode = kQ3FileModeDatabase;
    else
        fail(kQ3ErrorInvalidMetafilePrimitive, "the file mode '" + mode + "' is none of Normal, Stream, Database");
    std::vector<Node> tocs;
    while (!parser.done()) {
        if (parser.atLeftOver()) {
            errors::postWarning(kQ3WarningInvalidMetafileObject,
                                "what follows the last object (from line " + std::to_string(parser.leftOverLine()) +
                                    ") is no object; it is ignored");
            break;
        }
        Node node = parser.object(0);
        if (node.type == kTypeTableOfContents)
            tocs.push_back(std::move(node));
        else
            file.objects.push_back(std::move(node));
    }
    for (const Node& toc : tocs) {
        DataReader reader(file, toc);
        reader.u32(); // the next table of contents (a label reference in text)
        reader.u32(); // reference seed
        reader.i32(); // type seed
        const std::uint32_t entryType = reader.u32();
        reader.u32(); // entry size
        const std::uint32_t entries = reader.count(0, entryType == 1 ? 3 : 2, "table of contents entries");
        for (std::uint32_t i = 0; i < entries; ++i) {
            const std::uint32_t id = reader.u32();
            std::string label = reader.word();
            if (label.size() < 2 || label.back() != '>')
                fail(kQ3ErrorInvalidMetafileLabel, "table of contents entry " + std::to_string(id) + " names '" +
                                                       label + "', not a label ('name>')");
            label.pop_back();
            if (entryType == 1)
                reader.word(); // the object's type: a class name (or a number, as some writers put it)
            const Node* target = findLabel(file.objects, label);
            if (target == nullptr)
                fail(kQ3ErrorInvalidMetafileLabel, "table of contents entry " + std::to_string(id) +
                                                       " names the label " + label + ", which no object has");
            file.references[id] = target;
        }
    }
}

} // namespace

std::unique_ptr<Metafile> parse(std::vector<unsigned char> bytes, NameLookup names)
{
    if (bytes.size() > limits::kMaxStorageBytes)
        invalid("the file is larger than " + std::to_string(limits::kMaxStorageBytes) + " bytes");
    auto file = std::make_unique<Metafile>();
    file->bytes = std::move(bytes);
    const auto& b = file->bytes;
    if (b.size() >= 4 && std::memcmp(b.data(), "3DMF", 4) == 0)
        file->encoding = Encoding::kBinaryBig;
    else if (b.size() >= 4 && std::memcmp(b.data(), "FMD3", 4) == 0)
        file->encoding = Encoding::kBinaryLittle;
    else
        file->encoding = Encoding::kText;
    if (file->encoding == Encoding::kText) {
        std::size_t i = 0;
        while (i < b.size() && (std::isspace(b[i]) || b[i] == '#')) {
            if (b[i] == '#')
                while (i < b.size() && b[i] != '\n' && b[i] != '\r')
                    ++i;
            else
                ++i;
        }
        static const char kMagic[] = "3DMetafile";
        const std::size_t magic = sizeof kMagic - 1;
        if (b.size() - i < magic || !sameName(std::string(b.begin() + i, b.begin() + i + magic), kMagic))
            invalid("the file starts with neither the binary '3DMF' tag nor the text 3DMetafile header");
        parseText(*file, names);
    } else {
        parseBinary(*file, names);
    }
    if (file->major != 1)
        invalid("the file is version " + std::to_string(file->major) + "." + std::to_string(file->minor) +
                "; Q3 reads version 1 files");
    if (file->mode > kQ3FileModeDatabase)
        invalid("the file's mode " + std::to_string(file->mode) + " is none of Normal, Stream, Database");
    return file;
}

// ---- DataReader --------------------------------------------------------------

DataReader::DataReader(const Metafile& file, const Node& node)
    : m_file(file), m_node(node), m_position(file.encoding == Encoding::kText ? 0 : node.dataBegin)
{
}

std::size_t DataReader::remaining() const
{
    return m_file.encoding == Encoding::kText ? m_node.tokens.size() - std::min(m_position, m_node.tokens.size())
                                               : m_node.dataEnd - m_position;
}

bool DataReader::atEnd() const
{
    return m_file.encoding == Encoding::kText ? m_position >= m_node.tokens.size() : m_position >= m_node.dataEnd;
}

const unsigned char* DataReader::take(std::size_t n)
{
    if (m_node.dataEnd - m_position < n)
        fail(kQ3ErrorInvalidMetafilePrimitive,
             "the " + typeName(m_node.type) + " object's data end before all its fields were read");
    const unsigned char* p = m_file.bytes.data() + m_position;
    m_position += n;
    return p;
}

const std::string& DataReader::token()
{
    if (m_position >= m_node.tokens.size())
        fail(kQ3ErrorInvalidMetafilePrimitive, m_node.name + " ( ... ) ends before all its fields were read");
    return m_node.tokens[m_position++];
}

std::uint32_t DataReader::u32()
{
    if (m_file.encoding == Encoding::kText) {
        const std::string& t = token();
        if (!t.empty() && t.back() == '>')
            return 0; // a label reference (the header's and toc's next-toc field)
        return parseUnsigned(t, 0xFFFFFFFFull);
    }
    const unsigned char* p = take(4);
    return m_file.encoding == Encoding::kBinaryLittle
               ? (std::uint32_t{p[3]} << 24 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[1]} << 8 | p[0])
               : (std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3]);
}

std::int32_t DataReader::i32()
{
    if (m_file.encoding == Encoding::kText) {
        const std::string& t = token();
        if (std::uint32_t truth; booleanWord(t, truth))
            return static_cast<std::int32_t>(truth);
        errno = 0;
        char* end = nullptr;
        const long long value = std::strtoll(t.c_str(), &end, 0);
        if (errno != 0 || end == t.c_str() || *end != '\0' || value < INT32_MIN || value > INT32_MAX)
            fail(kQ3ErrorInvalidMetafilePrimitive, "'" + t + "' is not a 32-bit integer");
        return static_cast<std::int32_t>(value);
    }
    return static_cast<std::int32_t>(u32());
}

std::uint16_t DataReader::u16()
{
    if (m_file.encoding == Encoding::kText)
        return static_cast<std::uint16_t>(parseUnsigned(token(), 0xFFFF));
    const unsigned char* p = take(2);
    return m_file.encoding == Encoding::kBinaryLittle ? static_cast<std::uint16_t>(p[1] << 8 | p[0])
                                                      : static_cast<std::uint16_t>(p[0] << 8 | p[1]);
}

std::uint8_t DataReader::u8()
{
    if (m_file.encoding == Encoding::kText)
        return static_cast<std::uint8_t>(parseUnsigned(token(), 0xFF));
    return *take(1);
}

std::uint64_t DataReader::u64()
{
    if (m_file.encoding == Encoding::kText) {
        const std::string& t = token();
        if (!t.empty() && t.back() == '>')
            return 0;
        return parseUnsigned64(t);
    }
    const std::uint64_t first = u32();
    const std::uint64_t second = u32();
    return m_file.encoding == Encoding::kBinaryLittle ? (second << 32 | first) : (first << 32 | second);
}

float DataReader::f32()
{
    if (m_file.encoding == Encoding::kText) {
        const std::string& t = token();
        errno = 0;
        char* end = nullptr;
        const float value = std::strtof(t.c_str(), &end);
        if (end == t.c_str() || *end != '\0' || !std::isfinite(value))
            fail(kQ3ErrorInvalidMetafilePrimitive, "'" + t + "' is not a finite number");
        return value;
    }
    const std::uint32_t bits = u32();
    float value;
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isfinite(value))
        fail(kQ3ErrorInvalidMetafilePrimitive,
             "the " + typeName(m_node.type) + " object holds a number that is not finite");
    return value;
}

std::int8_t DataReader::i8()
{
    if (m_file.encoding == Encoding::kText)
        return static_cast<std::int8_t>(parseSigned(token(), INT8_MIN, INT8_MAX));
    return static_cast<std::int8_t>(u8());
}

std::int16_t DataReader::i16()
{
    if (m_file.encoding == Encoding::kText)
        return static_cast<std::int16_t>(parseSigned(token(), INT16_MIN, INT16_MAX));
    return static_cast<std::int16_t>(u16());
}

std::int64_t DataReader::i64()
{
    if (m_file.encoding == Encoding::kText)
        return parseSigned(token(), INT64_MIN, INT64_MAX);
    return static_cast<std::int64_t>(u64());
}

double DataReader::f64()
{
    if (m_file.encoding == Encoding::kText) {
        const std::string& t = token();
        char* end = nullptr;
        const double value = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || *end != '\0' || !std::isfinite(value))
            fail(kQ3ErrorInvalidMetafilePrimitive, "'" + t + "' is not a finite number");
        return value;
    }
    const std::uint64_t bits = u64();
    double value;
    std::memcpy(&value, &bits, sizeof value);
    if (!std::isfinite(value))
        fail(kQ3ErrorInvalidMetafilePrimitive,
             "the " + typeName(m_node.type) + " object holds a number that is not finite");
    return value;
}

std::string DataReader::string()
{
    if (m_file.encoding == Encoding::kText) {
        const std::string& t = token();
        if (t.size() < 2 || t.front() != '"' || t.back() != '"')
            fail(kQ3ErrorInvalidMetafilePrimitive, "'" + t + "' is not a quoted string");
        return t.substr(1, t.size() - 2);
    }
    const unsigned char* begin = m_file.bytes.data() + m_position;
    const std::size_t left = m_node.dataEnd - m_position;
    const void* nul = std::memchr(begin, 0, left);
    if (nul == nullptr)
        fail(kQ3ErrorInvalidMetafilePrimitive,
             "the " + typeName(m_node.type) + " object's data end inside a string (no terminating NUL)");
    const std::size_t length = static_cast<std::size_t>(static_cast<const unsigned char*>(nul) - begin);
    std::string out(reinterpret_cast<const char*>(begin), length);
    // The padding may be missing at the very end of the data.
    m_position += std::min(left, (length + 4) & ~std::size_t{3});
    return out;
}

std::string DataReader::rawData(std::size_t n)
{
    if (m_file.encoding == Encoding::kText) {
        // One or more 0x tokens, two hex digits a byte, n bytes in all (a
        // long run may be split over several tokens, as Quesa reads them).
        std::string out;
        out.reserve(std::min<std::size_t>(n, 1 << 20));
        while (out.size() < n) {
            const std::string& t = token();
            if (t.size() < 4 || t[0] != '0' || (t[1] != 'x' && t[1] != 'X') || (t.size() - 2) % 2 != 0 ||
                (t.size() - 2) / 2 > n - out.size())
                fail(kQ3ErrorInvalidMetafilePrimitive, "'" + t.substr(0, 40) + "' is not raw data of the " +
                                                           std::to_string(n - out.size()) +
                                                           " bytes left (0x and two hex digits a byte)");
            for (std::size_t i = 2; i < t.size(); i += 2) {
                if (!std::isxdigit(static_cast<unsigned char>(t[i])) ||
                    !std::isxdigit(static_cast<unsigned char>(t[i + 1])))
                    fail(kQ3ErrorInvalidMetafilePrimitive, "raw data holds '" + t.substr(i, 2) + "', not a hex byte");
                out.push_back(static_cast<char>(std::strtoul(t.substr(i, 2).c_str(), nullptr, 16)));
            }
        }
        return out;
    }
    const std::size_t padded = (n + 3) & ~std::size_t{3};
    if (m_node.dataEnd - m_position < n)
        fail(kQ3ErrorInvalidMetafilePrimitive, "the " + typeName(m_node.type) + " object's data end before " +
                                                   std::to_string(n) + " bytes of raw data");
    std::string out(reinterpret_cast<const char*>(m_file.bytes.data() + m_position), n);
    m_position += std::min(padded, m_node.dataEnd - m_position);
    return out;
}

// A braced list evaluates its elements in order, so the fields are read in
// the file's order.
TQ3Point3D DataReader::point3D()
{
    return {f32(), f32(), f32()};
}

TQ3Vector3D DataReader::vector3D()
{
    return {f32(), f32(), f32()};
}

TQ3ColorRGB DataReader::color()
{
    return {f32(), f32(), f32()};
}

TQ3Param2D DataReader::param2D()
{
    return {f32(), f32()};
}

TQ3RationalPoint4D DataReader::point4D()
{
    return {f32(), f32(), f32(), f32()};
}

std::uint32_t DataReader::choice(const std::vector<std::pair<const char*, std::uint32_t>>& names)
{
    if (m_file.encoding != Encoding::kText) {
        const std::uint32_t value = u32();
        for (const auto& [name, v] : names)
            if (v == value)
                return value;
        fail(kQ3ErrorInvalidMetafilePrimitive,
             "the " + typeName(m_node.type) + " object holds " + std::to_string(value) + ", which is none of its values");
    }
    const std::string& t = token();
    for (const auto& [name, v] : names)
        if (sameName(t, name))
            return v;
    // A two-valued choice (a TQ3Switch: Off 0, On 1) also reads True and
    // False, as other tools wrote a highlight state.
    std::uint32_t truth = 0;
    const bool twoValued = std::all_of(names.begin(), names.end(), [](const auto& n) { return n.second <= 1; });
    if (twoValued && booleanWord(t, truth))
        for (const auto& [name, v] : names)
            if (v == truth)
                return v;
    fail(kQ3ErrorInvalidMetafilePrimitive, "'" + t + "' is none of " + m_node.name + "'s values");
}

std::uint32_t DataReader::flags(const std::vector<std::pair<const char*, std::uint32_t>>& names)
{
    if (m_file.encoding != Encoding::kText)
        return u32();
    std::uint32_t value = 0;
    for (;;) {
        const std::string& t = token();
        bool found = false;
        for (const auto& [name, v] : names)
            if (sameName(t, name)) {
                value |= v;
                found = true;
            }
        if (!found)
            fail(kQ3ErrorInvalidMetafilePrimitive, "'" + t + "' is none of " + m_node.name + "'s flags");
        if (atEnd() || m_node.tokens[m_position] != "|")
            return value;
        ++m_position;
    }
}

std::uint32_t DataReader::count(std::size_t bytesPerItem, std::size_t tokensPerItem, const char* what)
{
    const std::uint32_t n = u32();
    requireRoom(n, bytesPerItem, tokensPerItem, what);
    return n;
}

bool DataReader::hasRoom(std::uint64_t n, std::size_t bytesPerItem, std::size_t tokensPerItem) const
{
    const std::size_t left = m_file.encoding == Encoding::kText ? m_node.tokens.size() - m_position
                                                                 : m_node.dataEnd - m_position;
    const std::size_t per = m_file.encoding == Encoding::kText ? tokensPerItem : bytesPerItem;
    return n <= limits::kMaxArrayCount && (per == 0 || n <= left / per);
}

void DataReader::requireRoom(std::uint64_t n, std::size_t bytesPerItem, std::size_t tokensPerItem,
                             const char* what) const
{
    if (!hasRoom(n, bytesPerItem, tokensPerItem))
        fail(kQ3ErrorInvalidMetafileObject, "the " + typeName(m_node.type) + " object claims " + std::to_string(n) +
                                                " " + what + ", more than its data can hold");
}

std::string DataReader::word()
{
    if (m_file.encoding != Encoding::kText)
        fail(kQ3ErrorInvalidMetafilePrimitive, "a word in a binary object");
    return token();
}

std::string DataReader::rest()
{
    std::string out;
    if (m_file.encoding == Encoding::kText) {
        for (; m_position < m_node.tokens.size(); ++m_position) {
            if (!out.empty())
                out += ' ';
            out += m_node.tokens[m_position];
        }
    } else {
        out.assign(reinterpret_cast<const char*>(m_file.bytes.data() + m_position), m_node.dataEnd - m_position);
        m_position = m_node.dataEnd;
    }
    return out;
}

// ---- Encoder -----------------------------------------------------------------

Encoder::Encoder(Encoding encoding) : m_encoding(encoding) {}

void Encoder::bytes(const void* data, std::size_t n, bool swap)
{
    const auto* p = static_cast<const unsigned char*>(data);
    // `data` is in the host's order (little-endian on every platform Q3
    // builds for, checked in finish()); big-endian files reverse it.
    if (swap && m_encoding == Encoding::kBinaryBig)
        for (std::size_t i = n; i-- > 0;)
            m_body.push_back(p[i]);
    else
        m_body.insert(m_body.end(), p, p + n);
}

void Encoder::word(const std::string& text)
{
    m_text += ' ';
    m_text += text;
}

void Encoder::begin(TQ3ObjectType type, const char* name)
{
    if (m_encoding == Encoding::kText) {
        if (!m_open.empty())
            m_open.back().hadChild = true;
        if (!m_text.empty() && m_text.back() != '\n')
            m_text += '\n';
        m_open.push_back({m_text.size(), false});
        m_text.append(2 * (m_open.size() - 1 + m_groupDepth), ' ');
        m_text += name;
        m_text += " (";
        return;
    }
    m_open.push_back({m_body.size(), false});
    if (isCustomType(type))
        type = customType(name);
    const std::uint32_t t = static_cast<std::uint32_t>(type);
    bytes(&t, 4, true);
    const std::uint32_t placeholder = 0;
    bytes(&placeholder, 4, true);
}

std::int32_t Encoder::customType(const std::string& name)
{
    // A class registered at run time: a file-local negative type, which a
    // Type object ahead of the objects names (3D Metafile Reference, "Type
    // objects").
    std::size_t index = 0;
    while (index < m_customTypes.size() && m_customTypes[index] != name)
        ++index;
    if (index == m_customTypes.size())
        m_customTypes.emplace_back(name);
    return -static_cast<std::int32_t>(index + 1);
}

void Encoder::end()
{
    const Open open = m_open.back();
    m_open.pop_back();
    if (m_encoding == Encoding::kText) {
        m_lastClose = m_text.size();
        if (open.hadChild) {
            m_text += '\n';
            m_text.append(2 * (m_open.size() + m_groupDepth), ' ');
            m_text += ")";
        } else {
            m_text += " )";
        }
        if (m_open.empty())
            m_text += '\n';
        return;
    }
    const std::uint32_t size = static_cast<std::uint32_t>(m_body.size() - open.start - 8);
    unsigned char* p = m_body.data() + open.start + 4;
    for (int i = 0; i < 4; ++i) {
        const int shift = m_encoding == Encoding::kBinaryBig ? 24 - 8 * i : 8 * i;
        p[i] = static_cast<unsigned char>(size >> shift);
    }
}

void Encoder::u32(std::uint32_t value)
{
    if (m_encoding == Encoding::kText)
        word(std::to_string(value));
    else
        bytes(&value, 4, true);
}

void Encoder::i32(std::int32_t value)
{
    if (m_encoding == Encoding::kText)
        word(std::to_string(value));
    else
        bytes(&value, 4, true);
}

void Encoder::u16(std::uint16_t value)
{
    if (m_encoding == Encoding::kText)
        word(std::to_string(value));
    else
        bytes(&value, 2, true);
}

void Encoder::u8(std::uint8_t value)
{
    if (m_encoding == Encoding::kText)
        word(std::to_string(value));
    else
        bytes(&value, 1, false);
}

void Encoder::u64(std::uint64_t value)
{
    if (m_encoding == Encoding::kText)
        word(std::to_string(value));
    else
        bytes(&value, 8, true);
}

void Encoder::f32(float value)
{
    if (m_encoding == Encoding::kText) {
        // The shortest form that reads back as the same float.
        char text[32];
        for (int digits = 6; digits <= 9; ++digits) {
            std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(value));
            if (std::strtof(text, nullptr) == value)
                break;
        }
        word(text);
    } else {
        bytes(&value, 4, true);
    }
}

void Encoder::f64(double value)
{
    if (m_encoding == Encoding::kText) {
        char text[40];
        for (int digits = 15; digits <= 17; ++digits) {
            std::snprintf(text, sizeof text, "%.*g", digits, value);
            if (std::strtod(text, nullptr) == value)
                break;
        }
        word(text);
    } else {
        bytes(&value, 8, true);
    }
}

void Encoder::string(const std::string& text)
{
    if (m_encoding == Encoding::kText) {
        std::string quoted = "\"";
        for (const char c : text) {
            if (c == '"' || c == '\\')
                quoted += '\\';
            quoted += c;
        }
        word(quoted + "\"");
        return;
    }
    m_body.insert(m_body.end(), text.begin(), text.end());
    m_body.insert(m_body.end(), 4 - text.size() % 4, 0);
}

void Encoder::rawData(const unsigned char* data, std::size_t n)
{
    if (m_encoding == Encoding::kText) {
        static const char kHex[] = "0123456789ABCDEF";
        std::string hex = "0x";
        for (std::size_t i = 0; i < n; ++i) {
            hex += kHex[data[i] >> 4];
            hex += kHex[data[i] & 15];
        }
        word(hex);
        return;
    }
    m_body.insert(m_body.end(), data, data + n);
    m_body.insert(m_body.end(), (4 - n % 4) % 4, 0);
}

void Encoder::comment(const std::string& text)
{
    if (m_encoding != Encoding::kText)
        return;
    if (!m_text.empty() && m_text.back() != '\n')
        m_text += '\n';
    m_text += "# ";
    for (const char c : text)
        m_text += (c == '\n' || c == '\r') ? ' ' : c;
    m_text += '\n';
}

void Encoder::newLine()
{
    if (m_encoding == Encoding::kText)
        m_text += '\n';
}

void Encoder::point3D(const TQ3Point3D& p)
{
    for (const float f : {p.x, p.y, p.z})
        f32(f);
}

void Encoder::vector3D(const TQ3Vector3D& v)
{
    for (const float f : {v.x, v.y, v.z})
        f32(f);
}

void Encoder::color(const TQ3ColorRGB& c)
{
    for (const float f : {c.r, c.g, c.b})
        f32(f);
}

void Encoder::param2D(const TQ3Param2D& p)
{
    for (const float f : {p.u, p.v})
        f32(f);
}

void Encoder::point4D(const TQ3RationalPoint4D& p)
{
    for (const float f : {p.x, p.y, p.z, p.w})
        f32(f);
}

void Encoder::choice(const std::vector<std::pair<const char*, std::uint32_t>>& names, std::uint32_t value)
{
    if (m_encoding != Encoding::kText) {
        u32(value);
        return;
    }
    for (const auto& [name, v] : names)
        if (v == value) {
            word(name);
            return;
        }
    u32(value);
}

void Encoder::flags(const std::vector<std::pair<const char*, std::uint32_t>>& names, std::uint32_t value)
{
    if (m_encoding != Encoding::kText) {
        u32(value);
        return;
    }
    std::string text;
    std::uint32_t left = value;
    for (const auto& [name, v] : names) {
        if (v != 0 && (left & v) == v) {
            text += (text.empty() ? "" : " | ") + std::string(name);
            left &= ~v;
        }
    }
    if (text.empty())
        for (const auto& [name, v] : names)
            if (v == 0)
                text = name;
    word(text);
}

void Encoder::raw(const std::string& data)
{
    if (m_encoding == Encoding::kText) {
        if (!data.empty())
            word(data);
    } else {
        m_body.insert(m_body.end(), data.begin(), data.end());
    }
}

void Encoder::rawObjects(const std::string& data, const std::map<std::uint32_t, std::string>& declared)
{
    const std::size_t start = m_body.size();
    m_body.insert(m_body.end(), data.begin(), data.end());
    if (declared.empty())
        return;
    const bool swap = m_encoding == Encoding::kBinaryLittle;
    const auto load = [&](std::size_t at) {
        std::uint32_t v;
        std::memcpy(&v, &m_body[at], 4);
        return swap ? v : (v >> 24 | (v >> 8 & 0xFF00) | (v << 8 & 0xFF0000) | v << 24);
    };
    const auto store = [&](std::size_t at, std::uint32_t v) {
        if (!swap)
            v = v >> 24 | (v >> 8 & 0xFF00) | (v << 8 & 0xFF0000) | v << 24;
        std::memcpy(&m_body[at], &v, 4);
    };
    // The objects' headers, inside containers and groups (the data of any
    // other object is opaque): each declared code becomes this file's code
    // for the same name.
    const auto walk = [&](auto& self, std::size_t at, std::size_t end) -> void {
        while (at + 8 <= end) {
            const std::uint32_t type = load(at);
            const std::size_t size = load(at + 4);
            if (size > end - at - 8)
                return; // checked when the file was parsed; never past the data
            if (const auto found = declared.find(type); found != declared.end())
                store(at, static_cast<std::uint32_t>(customType(found->second)));
            else if (type == static_cast<std::uint32_t>(kTypeContainer) ||
                     type == static_cast<std::uint32_t>(kTypeBeginGroup))
                self(self, at + 8, at + 8 + size);
            at += 8 + size;
        }
    };
    walk(walk, start, m_body.size());
}

std::size_t Encoder::reopenAsContainer(std::size_t start)
{
    if (m_encoding == Encoding::kText) {
        std::size_t first = start;
        while (first < m_text.size() && m_text[first] == ' ')
            ++first;
        if (m_text.compare(first, 11, "Container (") == 0) {
            m_text.resize(m_lastClose);
            m_open.push_back({start, true});
            return 0;
        }
        const std::string opening = std::string(first - start, ' ') + "Container (\n";
        m_text.insert(start, opening);
        for (auto& label : m_labels)
            if (label.first > start)
                label.first += opening.size();
        m_open.push_back({start, true});
        return opening.size();
    }
    std::uint32_t type = 0;
    for (int i = 0; i < 4; ++i) {
        const int shift = m_encoding == Encoding::kBinaryBig ? 24 - 8 * i : 8 * i;
        type |= static_cast<std::uint32_t>(m_body[start + i]) << shift;
    }
    if (type == static_cast<std::uint32_t>(kTypeContainer)) {
        m_open.push_back({start, true});
        return 0;
    }
    Encoder head(m_encoding);
    const std::uint32_t tag = static_cast<std::uint32_t>(kTypeContainer);
    head.bytes(&tag, 4, true);
    head.u32(0);
    m_body.insert(m_body.begin() + static_cast<std::ptrdiff_t>(start), head.m_body.begin(), head.m_body.end());
    m_open.push_back({start, true});
    return head.m_body.size();
}

std::size_t Encoder::position() const
{
    if (m_encoding == Encoding::kText)
        return m_text.size() + (!m_text.empty() && m_text.back() != '\n' ? 1 : 0);
    return m_body.size();
}

void Encoder::label(std::size_t position, const std::string& name)
{
    if (m_encoding == Encoding::kText)
        m_labels.emplace_back(position, name);
}

std::vector<unsigned char> Encoder::finish(TQ3FileMode mode, const std::vector<TocEntry>& toc)
{
    static_assert(sizeof(float) == 4, "3DMF floats are IEEE single precision");
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    if (first != 1)
        fail(kQ3ErrorInternalError, "Q3 writes binary 3DMF on little-endian hosts only");

    static const char* kModes[] = {"Normal", "Stream", "Database"};
    if (m_encoding == Encoding::kText) {
        std::sort(m_labels.begin(), m_labels.end());
        std::string text = m_text;
        for (auto it = m_labels.rbegin(); it != m_labels.rend(); ++it) {
            // Labels go after the object's indentation.
            std::size_t at = it->first;
            while (at < text.size() && text[at] == ' ')
                ++at;
            text.insert(at, it->second + ": ");
        }
        std::string out = "3DMetafile ( 1 6 " + std::string(kModes[mode & 3]) + (toc.empty() ? "" : " toc>") + " )\n";
        out += text;
        if (!toc.empty()) {
            // Next table, reference seed, type seed, entry type 1, entry
            // size 16, entry count.
            out += "toc: TableOfContents ( 0 " + std::to_string(toc.size() + 1) + " 0 1 16 " +
                   std::to_string(toc.size());
            // Text entries name the object's label (its position is the
            // label's); the type goes on a line of its own.
            for (const TocEntry& entry : toc)
                out += "\n  " + std::to_string(entry.id) + " ref" + std::to_string(entry.id) + ">\n  " + entry.name;
            out += "\n)\n";
        }
        return std::vector<unsigned char>(out.begin(), out.end());
    }

    Encoder head(m_encoding);
    const std::uint32_t tag = static_cast<std::uint32_t>(kTypeHeader);
    head.bytes(&tag, 4, true);
    head.u32(16);
    const std::uint32_t version = m_encoding == Encoding::kBinaryBig ? (1u << 16 | 6u) : (6u << 16 | 1u);
    head.u32(version);
    head.u32(mode & 3);
    // Type objects for the custom classes, ahead of every object.
    Encoder types(m_encoding);
    for (std::size_t i = 0; i < m_customTypes.size(); ++i) {
        types.begin(kTypeType, "Type");
        types.i32(-static_cast<std::int32_t>(i + 1));
        types.string(m_customTypes[i]);
        types.end();
    }
    const std::size_t bodyStart = 24 + types.m_body.size();
    const std::uint64_t tocOffset = toc.empty() ? 0 : bodyStart + m_body.size();
    head.u64(tocOffset);
    std::vector<unsigned char> out = std::move(head.m_body);
    out.insert(out.end(), types.m_body.begin(), types.m_body.end());
    out.insert(out.end(), m_body.begin(), m_body.end());
    if (!toc.empty()) {
        Encoder table(m_encoding);
        table.begin(kTypeTableOfContents, "TableOfContents");
        table.u64(0);
        table.u32(static_cast<std::uint32_t>(toc.size() + 1));
        table.i32(0);
        table.u32(1);
        table.u32(16);
        table.u32(static_cast<std::uint32_t>(toc.size()));
        for (const TocEntry& entry : toc) {
            table.u32(entry.id);
            table.u64(bodyStart + entry.position);
            // A custom class's entry has the file's code for it, as its
            // object does (the name is declared already: the object was written).
            table.u32(static_cast<std::uint32_t>(isCustomType(entry.type) ? customType(entry.name) : entry.type));
        }
        table.end();
        out.insert(out.end(), table.m_body.begin(), table.m_body.end());
    }
    return out;
}

} // namespace q3::io
