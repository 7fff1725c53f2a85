// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The 3DMF container format, apart from what any class's data means: the
// header, objects (a type, a size and data), containers, groups, references
// and the table of contents, in the two encodings (3D Metafile Reference,
// chapter 1):
//
//   binary  every object is a four-character type, a 32-bit size and that
//           many bytes of data; big-endian as Mac QuickDraw 3D wrote it, or
//           little-endian (the header's tag then reads "FMD3").
//   text    every object is `[label:] Name ( data )`; data are numbers, words
//           and "strings"; `#` starts a comment.
//
// parse() turns a whole file into a tree of Nodes and checks everything the
// format itself promises: sizes inside their container, nesting within
// limits::kMaxMetafileNesting, every reference in the table of contents
// pointing at an object. DataReader then reads one object's data, refusing
// anything past its end; Encoder writes objects in either encoding.

#include "QD3D.h"
#include "QD3DIO.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace q3::io {

constexpr TQ3ObjectType kTypeHeader = Q3_OBJECT_TYPE('3', 'D', 'M', 'F');
constexpr TQ3ObjectType kTypeContainer = Q3_OBJECT_TYPE('c', 'n', 't', 'r');
constexpr TQ3ObjectType kTypeBeginGroup = Q3_OBJECT_TYPE('b', 'g', 'n', 'g');
constexpr TQ3ObjectType kTypeEndGroup = Q3_OBJECT_TYPE('e', 'n', 'd', 'g');
constexpr TQ3ObjectType kTypeReference = Q3_OBJECT_TYPE('r', 'f', 'r', 'n');
constexpr TQ3ObjectType kTypeTableOfContents = Q3_OBJECT_TYPE('t', 'o', 'c', ' ');
/// Binary files: names a file-local negative type (Int32 type, String name).
constexpr TQ3ObjectType kTypeType = Q3_OBJECT_TYPE('t', 'y', 'p', 'e');

enum class Encoding { kBinaryBig, kBinaryLittle, kText };

/// One object of a file. Binary objects keep their data as a byte range of
/// the file; text objects as their tokens. `children` are the objects inside
/// a container or a BeginGroup (binary) or every object nested in the
/// parentheses (text).
struct Node {
    TQ3ObjectType type = 0; ///< 0: a text name no class has
    std::string name;       ///< the text name as written (text files)
    std::string label;      ///< the text label, without its ':'
    std::size_t offset = 0; ///< binary: where the object starts in the file
    std::size_t dataBegin = 0, dataEnd = 0;
    std::vector<std::string> tokens;
    std::vector<Node> children;
};

/// A parsed file. Invariant: every Node reachable from `objects` is within
/// the file and the nesting limit; `references` point into `objects`' trees.
struct Metafile {
    Encoding encoding = Encoding::kBinaryBig;
    std::vector<unsigned char> bytes;
    TQ3FileMode mode = kQ3FileModeNormal;
    std::uint32_t major = 1, minor = 6;
    std::vector<Node> objects; ///< the objects after the header, without tables of contents
    std::map<std::uint32_t, const Node*> references;
};

/// The type a text name stands for (0 when no class has it); the parser asks
/// it for every object name. Names compare without regard to case.
using NameLookup = TQ3ObjectType (*)(const std::string& name);

/// Parses a whole file. Throws q3::Error: kQ3ErrorInvalidMetafile (no 3DMF
/// header, a version other than 1.x, a truncated object, a size overrunning
/// its container, nesting too deep), kQ3ErrorInvalidMetafilePrimitive (a
/// malformed token), kQ3ErrorInvalidMetafileLabel (a table of contents
/// entry naming nothing).
std::unique_ptr<Metafile> parse(std::vector<unsigned char> bytes, NameLookup names);

/// Reads one object's data in order. Every read past the end of the data,
/// and every malformed number, throws kQ3ErrorInvalidMetafilePrimitive.
class DataReader {
public:
    DataReader(const Metafile& file, const Node& node);

    std::uint32_t u32();
    std::int32_t i32();
    std::uint16_t u16();
    std::uint8_t u8();
    std::uint64_t u64();
    float f32();
    /// Signed forms for the primitive calls (text: a decimal with its sign).
    std::int8_t i8();
    std::int16_t i16();
    std::int64_t i64();
    double f64();
    /// A string: NUL-terminated and padded to 4 bytes (binary), a quoted
    /// token (text). Refuses a binary string without its NUL.
    std::string string();
    /// `n` raw bytes: padded to 4 bytes (binary), one `0x` hexadecimal token
    /// (text).
    std::string rawData(std::size_t n);
    TQ3Point3D point3D();
    TQ3Vector3D vector3D();
    TQ3ColorRGB color();
    TQ3Param2D param2D();
    TQ3RationalPoint4D point4D();
    /// An enumeration: a word in text, a 32-bit value in binary.
    std::uint32_t choice(const std::vector<std::pair<const char*, std::uint32_t>>& names);
    /// A set of flags: words joined by '|' in text, a 32-bit value in binary.
    std::uint32_t flags(const std::vector<std::pair<const char*, std::uint32_t>>& names);
    /// A count of items each needing at least `bytesPerItem` bytes (binary) or
    /// `tokensPerItem` tokens (text): refused (kQ3ErrorInvalidMetafileObject)
    /// when the object's data cannot hold that many, so no count makes Q3
    /// allocate more than the file justifies.
    std::uint32_t count(std::size_t bytesPerItem, std::size_t tokensPerItem, const char* what);
    /// Refuses (kQ3ErrorInvalidMetafileObject) `n` items of that size when
    /// the rest of the data cannot hold them.
    void requireRoom(std::uint64_t n, std::size_t bytesPerItem, std::size_t tokensPerItem, const char* what) const;
    /// Whether the rest of the data can hold `n` such items.
    bool hasRoom(std::uint64_t n, std::size_t bytesPerItem, std::size_t tokensPerItem) const;
    bool atEnd() const;
    /// Binary bytes or text tokens not read yet.
    std::size_t remaining() const;
    /// Where the reader is, to come back to after a failed read.
    std::size_t tell() const { return m_position; }
    void seek(std::size_t position) { m_position = position; }
    /// Text: the next token as it is.
    std::string word();
    /// The rest of the data, as it is (binary bytes, or text tokens joined
    /// by spaces).
    std::string rest();

private:
    const unsigned char* take(std::size_t n);
    const std::string& token();

    const Metafile& m_file;
    const Node& m_node;
    std::size_t m_position; // byte (binary) or token (text) index
};

/// Writes objects in one encoding. Objects nest: begin ... end, with data in
/// between and nested objects (children) anywhere after the data.
class Encoder {
public:
    explicit Encoder(Encoding encoding);

    Encoding encoding() const { return m_encoding; }
    void begin(TQ3ObjectType type, const char* name);
    void end();
    /// Text: the objects between a BeginGroup and its EndGroup are indented
    /// one more step.
    void enterGroup() { ++m_groupDepth; }
    void leaveGroup() { --m_groupDepth; }

    void u32(std::uint32_t value);
    void i32(std::int32_t value);
    void u16(std::uint16_t value);
    void u8(std::uint8_t value);
    void u64(std::uint64_t value);
    void f32(float value);
    void f64(double value);
    /// As DataReader::string and DataReader::rawData read them.
    void string(const std::string& text);
    void rawData(const unsigned char* data, std::size_t n);
    /// Text: `# comment` on a line of its own; a line break. Binary: nothing.
    void comment(const std::string& text);
    void newLine();
    void point3D(const TQ3Point3D& p);
    void vector3D(const TQ3Vector3D& v);
    void color(const TQ3ColorRGB& c);
    void param2D(const TQ3Param2D& p);
    void point4D(const TQ3RationalPoint4D& p);
    void choice(const std::vector<std::pair<const char*, std::uint32_t>>& names, std::uint32_t value);
    void flags(const std::vector<std::pair<const char*, std::uint32_t>>& names, std::uint32_t value);
    /// Data copied as it is (an unknown object's).
    void raw(const std::string& data);
    /// Binary: the data of an unknown container or group (a sequence of
    /// objects) copied, with the custom types `declared` names (their codes
    /// in the file they came from) renumbered as this file declares them.
    void rawObjects(const std::string& data, const std::map<std::uint32_t, std::string>& declared);
    /// Binary: this file's code for a custom class name, declared by a Type
    /// object ahead of the objects.
    std::int32_t customType(const std::string& name);

    /// A point to come back to: rollback(mark()) forgets everything written
    /// since (what a failed write leaves behind).
    struct Mark {
        std::size_t body, text, open, labels, groupDepth, customTypes;
    };
    Mark mark() const
    {
        return {m_body.size(), m_text.size(), m_open.size(), m_labels.size(), m_groupDepth, m_customTypes.size()};
    }
    void rollback(const Mark& at)
    {
        m_customTypes.resize(at.customTypes);
        m_body.resize(at.body);
        m_text.resize(at.text);
        m_open.resize(at.open);
        m_labels.resize(at.labels);
        m_groupDepth = at.groupDepth;
    }

    /// Makes the object written last, which starts at `start` (its
    /// position() before it began), an open container again: its own end is
    /// undone when it is a Container, else a Container is begun before it.
    /// What is written next goes into that container, up to end(). Returns
    /// how far everything after `start` moved (the inserted Container's
    /// bytes or characters), for positions kept outside the encoder.
    std::size_t reopenAsContainer(std::size_t start);

    /// Where the next object starts (binary: its byte offset in the body).
    std::size_t position() const;
    /// Text: gives the object starting at `position` a label (inserted at
    /// finish). Binary: nothing.
    void label(std::size_t position, const std::string& name);
    /// One table of contents entry: a reference ID, where its object starts
    /// in the body, and the object's type (its text name for text files).
    struct TocEntry {
        std::uint32_t id;
        std::size_t position;
        TQ3ObjectType type;
        const char* name;
    };
    /// The whole file: header (mode, and a table of contents of the given
    /// entries) followed by the objects written. The table's entries carry
    /// their object types (entry type 1), as QuickDraw 3D 1.5 and later
    /// write them: its Q3File_GetExternalReferences finds a file's
    /// ExternalReference objects through those types.
    std::vector<unsigned char> finish(TQ3FileMode mode, const std::vector<TocEntry>& toc);

private:
    void word(const std::string& text);
    void bytes(const void* data, std::size_t n, bool swap);

    Encoding m_encoding;
    std::vector<unsigned char> m_body;
    std::string m_text;
    struct Open {
        std::size_t start;
        bool hadChild;
    };
    std::vector<Open> m_open;
    std::vector<std::pair<std::size_t, std::string>> m_labels;
    std::size_t m_groupDepth = 0;
    /// Text: where the last end() began writing its ')' (for
    /// reopenAsContainer).
    std::size_t m_lastClose = 0;
    /// Binary: the file-local negative type of each custom class written
    /// (by name), declared by Type objects ahead of the objects.
    std::vector<std::string> m_customTypes;
};

/// The four characters of a type, for messages ('trng').
std::string typeName(TQ3ObjectType type);

/// Whether a type is a custom class's: negative as a 32-bit value (a binary
/// file's types are read as 32-bit patterns into the wider TQ3ObjectType,
/// so a file-local type -1 arrives as 0xFFFFFFFF).
inline bool isCustomType(TQ3ObjectType type)
{
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(type)) < 0;
}

} // namespace q3::io
