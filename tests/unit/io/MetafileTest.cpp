// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// io/Metafile at the unit level, below the file objects the API tests use:
// the text tokenizer (spaces, parentheses, bars, comments, strings, labels,
// the three line endings), the two binary byte orders and the text encoding
// read through DataReader from files written here byte by byte, the limits
// the parser and the reader keep, references through the table of contents
// (and ReadContext resolving Reference objects through it: two references
// give one object), and the Encoder's output read back in every encoding.

#include "QD3DGeometry.h"
#include "core/Error.h"
#include "core/Limits.h"
#include "io/ClassIO.h"
#include "io/Metafile.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace q3;
using namespace q3::io;

constexpr TQ3ObjectType kPointType = Q3_OBJECT_TYPE('p', 'n', 't', ' ');

// The names these tests use: "Point" and "Thing", in any case.
TQ3ObjectType names(const std::string& name)
{
    std::string lower;
    for (char c : name)
        lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "point")
        return kPointType;
    return 0;
}

std::vector<unsigned char> bytesOf(const std::string& text)
{
    return std::vector<unsigned char>(text.begin(), text.end());
}

std::unique_ptr<Metafile> parseText(const std::string& text)
{
    return parse(bytesOf(text), names);
}

/// The code a call throws as q3::Error (kQ3ErrorNone when it does not).
TQ3Error codeOf(const std::function<void()>& call)
{
    try {
        call();
    } catch (const Error& error) {
        return error.code();
    }
    return kQ3ErrorNone;
}

const std::string kTextHeader = "3DMetafile ( 1 6 Normal )\n";

// A binary file built byte by byte, in either byte order.
class BinaryWriter {
public:
    explicit BinaryWriter(bool little) : m_little(little) {}

    void u32(std::uint32_t v)
    {
        for (int i = 0; i < 4; ++i)
            m_bytes.push_back(static_cast<unsigned char>(v >> (m_little ? 8 * i : 24 - 8 * i)));
    }
    void u64(std::uint64_t v)
    {
        if (m_little) {
            u32(static_cast<std::uint32_t>(v));
            u32(static_cast<std::uint32_t>(v >> 32));
        } else {
            u32(static_cast<std::uint32_t>(v >> 32));
            u32(static_cast<std::uint32_t>(v));
        }
    }
    void f32(float f)
    {
        std::uint32_t bits;
        std::memcpy(&bits, &f, 4);
        u32(bits);
    }
    /// The header: version 1.6, Normal, the table of contents' offset.
    void header(std::uint64_t toc = 0)
    {
        u32(Q3_OBJECT_TYPE('3', 'D', 'M', 'F'));
        u32(16);
        u32(m_little ? (6u << 16 | 1u) : (1u << 16 | 6u));
        u32(kQ3FileModeNormal);
        u64(toc);
    }
    void object(TQ3ObjectType type, std::uint32_t size)
    {
        u32(static_cast<std::uint32_t>(type));
        u32(size);
    }
    std::size_t size() const { return m_bytes.size(); }
    std::vector<unsigned char>& bytes() { return m_bytes; }

private:
    bool m_little;
    std::vector<unsigned char> m_bytes;
};

// ---- The tokenizer ---------------------------------------------------------------

TEST(MetafileText, TokensAreSplitAtSpacesParenthesesAndBarsAndCommentsAreSkipped)
{
    const auto file = parseText(kTextHeader + "Point ( 1\t2.5 -3 # a comment ( with a parenthesis\n)\n"
                                              "Thing (A|B  \"a (string) # kept\" 0x0F)\n");
    ASSERT_EQ(file->objects.size(), 2u);
    EXPECT_EQ(file->objects[0].type, kPointType);
    EXPECT_EQ(file->objects[0].tokens, (std::vector<std::string>{"1", "2.5", "-3"}));
    EXPECT_EQ(file->objects[1].type, 0); // a name no class has
    EXPECT_EQ(file->objects[1].name, "Thing");
    EXPECT_EQ(file->objects[1].tokens,
              (std::vector<std::string>{"A", "|", "B", "\"a (string) # kept\"", "0x0F"}));
}

TEST(MetafileText, AStringKeepsEscapedQuotesAndAnUnclosedStringIsRefused)
{
    const auto file = parseText(kTextHeader + "Thing ( \"say \\\"hi\\\"\" )\n");
    DataReader reader(*file, file->objects[0]);
    EXPECT_EQ(reader.string(), "say \"hi\"");
    EXPECT_TRUE(reader.atEnd());
    EXPECT_EQ(codeOf([] { parseText(kTextHeader + "Thing ( \"open )\n"); }), kQ3ErrorInvalidMetafilePrimitive);
}

TEST(MetafileText, LinesEndAtLfCrOrCrLf)
{
    // node.offset of a text object is the line it starts on.
    for (const std::string& end : {std::string("\n"), std::string("\r"), std::string("\r\n")}) {
        SCOPED_TRACE(end == "\n" ? "LF" : end == "\r" ? "CR" : "CRLF");
        const std::string text = "3DMetafile ( 1 6 Normal )" + end + "Point ( 1 2 3 )" + end + end +
                                 "Point ( 4 # comment" + end + "5 6 )" + end + "Point ( \"two" + end + "lines\" )";
        const auto file = parseText(text);
        ASSERT_EQ(file->objects.size(), 3u);
        EXPECT_EQ(file->objects[0].offset, 2u);
        EXPECT_EQ(file->objects[1].offset, 4u);
        EXPECT_EQ(file->objects[1].tokens, (std::vector<std::string>{"4", "5", "6"}));
        EXPECT_EQ(file->objects[2].offset, 6u);
    }
    // A mixed file counts each ending once.
    const auto mixed = parseText("3DMetafile ( 1 6 Normal )\r\n\r\n\nPoint ( 1 2 3 )");
    EXPECT_EQ(mixed->objects[0].offset, 4u); // CRLF, CRLF, LF: three line ends
}

TEST(MetafileText, LabelsNamesAndNestingAreRead)
{
    const auto file = parseText(kTextHeader + "first: CONTAINER ( pOiNt ( 1 2 3 ) inner: Thing ( ) )\n");
    ASSERT_EQ(file->objects.size(), 1u);
    const Node& container = file->objects[0];
    EXPECT_EQ(container.label, "first");
    EXPECT_EQ(container.type, kTypeContainer); // names compare without regard to case
    ASSERT_EQ(container.children.size(), 2u);
    EXPECT_EQ(container.children[0].type, kPointType);
    EXPECT_EQ(container.children[1].label, "inner");
    EXPECT_TRUE(container.tokens.empty());
}

TEST(MetafileText, MalformedObjectsAreRefusedWithTheirCodes)
{
    EXPECT_EQ(codeOf([] { parseText(""); }), kQ3ErrorInvalidMetafile);
    EXPECT_EQ(codeOf([] { parseText("Point ( 1 2 3 )"); }), kQ3ErrorInvalidMetafile); // no header
    EXPECT_EQ(codeOf([] { parseText("3DMetafile ( 1 6 )"); }), kQ3ErrorInvalidMetafile);
    EXPECT_EQ(codeOf([] { parseText("3DMetafile ( 1 6 Sideways )"); }), kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_EQ(codeOf([] { parseText(kTextHeader + "Point ( 1 2 3"); }), kQ3ErrorInvalidMetafile);
    EXPECT_EQ(codeOf([] { parseText(kTextHeader + "Point 1 2 3 )"); }), kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_EQ(codeOf([] { parseText(kTextHeader + "Point ( ( 1 ) )"); }), kQ3ErrorInvalidMetafilePrimitive);
    EXPECT_EQ(codeOf([] { parseText(kTextHeader + "12 ( )"); }), kQ3ErrorInvalidMetafilePrimitive);
}

TEST(MetafileText, NestingIsLimited)
{
    auto nested = [](std::size_t depth) {
        std::string text = kTextHeader;
        for (std::size_t i = 0; i < depth; ++i)
            text += "Container ( ";
        for (std::size_t i = 0; i < depth; ++i)
            text += ") ";
        return text;
    };
    EXPECT_EQ(codeOf([&] { parseText(nested(limits::kMaxMetafileNesting + 1)); }), kQ3ErrorNone);
    EXPECT_EQ(codeOf([&] { parseText(nested(limits::kMaxMetafileNesting + 2)); }), kQ3ErrorInvalidMetafile);
}

// ---- Encodings ---------------------------------------------------------------------

// The same object in the three encodings: a point (1, -2.5, 3e-3), an
// unsigned 32-bit 4000000000, a signed -7, a string "ab".
std::vector<unsigned char> sampleFile(Encoding encoding)
{
    if (encoding == Encoding::kText)
        return bytesOf(kTextHeader + "Thing ( 1 -2.5 3e-3 4000000000 -7 \"ab\" )\n");
    BinaryWriter w(encoding == Encoding::kBinaryLittle);
    w.header();
    w.object(Q3_OBJECT_TYPE('t', 'h', 'n', 'g'), 12 + 4 + 4 + 4);
    w.f32(1);
    w.f32(-2.5f);
    w.f32(3e-3f);
    w.u32(4000000000u);
    w.u32(static_cast<std::uint32_t>(-7));
    w.bytes().insert(w.bytes().end(), {'a', 'b', 0, 0}); // NUL-terminated, padded to 4
    return w.bytes();
}

TEST(MetafileEncoding, TheThreeEncodingsReadTheSameValues)
{
    for (Encoding encoding : {Encoding::kBinaryBig, Encoding::kBinaryLittle, Encoding::kText}) {
        SCOPED_TRACE(int(encoding));
        const auto file = parse(sampleFile(encoding), names);
        EXPECT_EQ(file->encoding, encoding);
        EXPECT_EQ(file->major, 1u);
        EXPECT_EQ(file->minor, 6u);
        EXPECT_EQ(file->mode, kQ3FileModeNormal);
        ASSERT_EQ(file->objects.size(), 1u);
        DataReader reader(*file, file->objects[0]);
        const TQ3Point3D p = reader.point3D();
        EXPECT_EQ(p.x, 1.0f);
        EXPECT_EQ(p.y, -2.5f);
        EXPECT_EQ(p.z, 3e-3f);
        EXPECT_EQ(reader.u32(), 4000000000u);
        EXPECT_EQ(reader.i32(), -7);
        EXPECT_EQ(reader.string(), "ab");
        EXPECT_TRUE(reader.atEnd());
        // Nothing is read past the end.
        EXPECT_EQ(codeOf([&] { reader.u32(); }), kQ3ErrorInvalidMetafilePrimitive);
        EXPECT_EQ(codeOf([&] { reader.f32(); }), kQ3ErrorInvalidMetafilePrimitive);
    }
}

TEST(MetafileEncoding, ABinaryHeaderGivesTheByteOrderAndTheVersion)
{
    const std::vector<unsigned char> big = sampleFile(Encoding::kBinaryBig);
    const std::vector<unsigned char> little = sampleFile(Encoding::kBinaryLittle);
    EXPECT_EQ(std::string(big.begin(), big.begin() + 4), "3DMF");
    EXPECT_EQ(std::string(little.begin(), little.begin() + 4), "FMD3");
    // Version 2.0 is not 1.x.
    BinaryWriter w(false);
    w.header();
    w.bytes()[8] = 0;
    w.bytes()[9] = 2;
    w.bytes()[10] = 0;
    w.bytes()[11] = 0;
    EXPECT_EQ(codeOf([&] { parse(w.bytes(), names); }), kQ3ErrorInvalidMetafile);
    // A header that is not 16 bytes long.
    BinaryWriter odd(true);
    odd.header();
    odd.bytes()[4] = 17;
    EXPECT_EQ(codeOf([&] { parse(odd.bytes(), names); }), kQ3ErrorInvalidMetafile);
}

TEST(MetafileEncoding, NumbersThatAreNotFiniteOrMalformedAreRefused)
{
    for (const char* bad : {"nan", "inf", "-inf", "1e99", "1.5.2", "x"}) {
        const auto file = parseText(kTextHeader + "Thing ( " + bad + " )");
        DataReader reader(*file, file->objects[0]);
        EXPECT_EQ(codeOf([&] { reader.f32(); }), kQ3ErrorInvalidMetafilePrimitive) << bad;
    }
    for (const char* bad : {"-1", "4294967296", "12abc"}) {
        const auto file = parseText(kTextHeader + "Thing ( " + bad + " )");
        DataReader reader(*file, file->objects[0]);
        EXPECT_EQ(codeOf([&] { reader.u32(); }), kQ3ErrorInvalidMetafilePrimitive) << bad;
    }
    for (bool little : {false, true}) {
        BinaryWriter w(little);
        w.header();
        w.object(Q3_OBJECT_TYPE('t', 'h', 'n', 'g'), 8);
        w.f32(std::numeric_limits<float>::quiet_NaN());
        w.f32(std::numeric_limits<float>::infinity());
        const auto file = parse(w.bytes(), names);
        DataReader reader(*file, file->objects[0]);
        const std::size_t start = reader.tell();
        EXPECT_EQ(codeOf([&] { reader.f32(); }), kQ3ErrorInvalidMetafilePrimitive);
        reader.seek(start + 4);
        EXPECT_EQ(codeOf([&] { reader.f32(); }), kQ3ErrorInvalidMetafilePrimitive);
    }
}

TEST(MetafileEncoding, ACountTheDataCannotHoldIsRefusedBeforeAnythingIsAllocated)
{
    for (bool little : {false, true}) {
        BinaryWriter w(little);
        w.header();
        w.object(Q3_OBJECT_TYPE('t', 'h', 'n', 'g'), 4 + 24);
        w.u32(3); // three 8-byte items: 24 bytes follow, enough
        for (int i = 0; i < 6; ++i)
            w.f32(float(i));
        const auto file = parse(w.bytes(), names);
        DataReader fits(*file, file->objects[0]);
        EXPECT_EQ(fits.count(8, 2, "items"), 3u);
        DataReader tooMany(*file, file->objects[0]);
        EXPECT_EQ(codeOf([&] { tooMany.count(9, 2, "items"); }), kQ3ErrorInvalidMetafileObject);
    }
    const auto text = parseText(kTextHeader + "Thing ( 2 1 2 3 )");
    DataReader tokens(*text, text->objects[0]);
    EXPECT_EQ(codeOf([&] { tokens.count(0, 2, "items"); }), kQ3ErrorInvalidMetafileObject);
}

// A binary file holding a container that claims `containerSize` bytes of
// data and holds a point (1, 2, 3): 8 bytes of header and 12 of data.
std::vector<unsigned char> containedPoint(bool little, std::uint32_t containerSize)
{
    BinaryWriter w(little);
    w.header();
    w.object(kTypeContainer, containerSize);
    w.object(kPointType, 12);
    w.f32(1);
    w.f32(2);
    w.f32(3);
    return w.bytes();
}

TEST(MetafileEncoding, SizesMustStayInsideTheirContainer)
{
    for (bool little : {false, true}) {
        SCOPED_TRACE(little ? "little" : "big");
        // A container of 16 bytes holding an object that claims 12 bytes of
        // data: 8 + 12 overruns it.
        // The point's third coordinate lies beyond the container, inside the file.
        EXPECT_EQ(codeOf([&] { parse(containedPoint(little, 16), names); }), kQ3ErrorInvalidMetafile);
        // A truncated last object (its size overruns the file).
        BinaryWriter t(little);
        t.header();
        t.object(kPointType, 12);
        t.f32(1);
        EXPECT_EQ(codeOf([&] { parse(t.bytes(), names); }), kQ3ErrorInvalidMetafile);
        // A well-formed container: the child is found.
        const auto file = parse(containedPoint(little, 20), names);
        ASSERT_EQ(file->objects.size(), 1u);
        ASSERT_EQ(file->objects[0].children.size(), 1u);
        EXPECT_EQ(file->objects[0].children[0].offset, 32u);
        DataReader reader(*file, file->objects[0].children[0]);
        EXPECT_EQ(reader.point3D().z, 3.0f);
    }
}

// ---- References and the table of contents --------------------------------------------

// A binary file: a point at byte 24, a table of contents after it whose one
// entry (id 7, type-less entries) points at `target`.
std::vector<unsigned char> fileWithToc(bool little, std::uint64_t target)
{
    BinaryWriter w(little);
    const std::uint64_t tocAt = 24 + 8 + 12;
    w.header(tocAt);
    w.object(kPointType, 12);
    w.f32(1);
    w.f32(2);
    w.f32(3);
    w.object(kTypeTableOfContents, 8 + 4 + 4 + 4 + 4 + 4 + 12);
    w.u64(0); // no next table
    w.u32(8); // reference seed
    w.u32(0); // type seed
    w.u32(0); // entry type 0: id and location
    w.u32(12);
    w.u32(1);
    w.u32(7);
    w.u64(target);
    return w.bytes();
}

TEST(MetafileReferences, ABinaryTableOfContentsMapsIdsToObjects)
{
    for (bool little : {false, true}) {
        SCOPED_TRACE(little ? "little" : "big");
        const auto file = parse(fileWithToc(little, 24), names);
        ASSERT_EQ(file->objects.size(), 1u); // the table is not an object of the file
        ASSERT_EQ(file->references.count(7), 1u);
        EXPECT_EQ(file->references.at(7), &file->objects[0]);
        // An entry pointing where no object starts.
        EXPECT_EQ(codeOf([&] { parse(fileWithToc(little, 28), names); }), kQ3ErrorInvalidMetafileLabel);
        // A header offset where no table of contents is.
        std::vector<unsigned char> bytes = fileWithToc(little, 24);
        bytes[little ? 16 : 23] = 24;
        EXPECT_EQ(codeOf([&] { parse(bytes, names); }), kQ3ErrorInvalidMetafile);
    }
}

TEST(MetafileReferences, ATextTableOfContentsNamesLabels)
{
    const std::string head = "3DMetafile ( 1 6 Normal toc> )\n";
    const auto file = parseText(head + "Container ( Thing ( ) deep: Point ( 1 2 3 ) )\n"
                                       "toc: TableOfContents ( 0 3 0 1 16 2\n"
                                       "  1 deep> Point\n  2 top> Container\n)\ntop: Point ( 4 5 6 )\n");
    ASSERT_EQ(file->objects.size(), 2u);
    ASSERT_EQ(file->references.size(), 2u);
    EXPECT_EQ(file->references.at(1), &file->objects[0].children[1]); // found inside a container
    EXPECT_EQ(file->references.at(2), &file->objects[1]);             // a label after the table
    EXPECT_EQ(codeOf([&] {
                  parseText(head + "a: Point ( 1 2 3 )\ntoc: TableOfContents ( 0 2 0 0 12 1 1 nowhere> )\n");
              }),
              kQ3ErrorInvalidMetafileLabel);
    EXPECT_EQ(codeOf([&] { parseText(head + "a: Point ( 1 2 3 )\ntoc: TableOfContents ( 0 2 0 0 12 1 1 a )\n"); }),
              kQ3ErrorInvalidMetafileLabel); // not written as a label
}

// ---- The encoder, read back -------------------------------------------------------------

TEST(MetafileEncoder, WhatItWritesReadsBackInEveryEncoding)
{
    for (Encoding encoding : {Encoding::kBinaryBig, Encoding::kBinaryLittle, Encoding::kText}) {
        SCOPED_TRACE(int(encoding));
        Encoder out(encoding);
        out.begin(kTypeContainer, "Container");
        const std::size_t at = out.position();
        out.label(at, "ref1");
        out.begin(kPointType, "Point");
        out.point3D({1, -2.5f, 3e-3f});
        out.end();
        out.begin(kPointType, "Point");
        out.u32(4000000000u);
        out.i32(-7);
        out.string("a \"quoted\" word");
        out.end();
        out.end();
        const auto file = parse(out.finish(kQ3FileModeStream, {{1, at, kPointType, "Point"}}), names);
        EXPECT_EQ(file->encoding, encoding);
        EXPECT_EQ(file->mode, kQ3FileModeStream);
        ASSERT_EQ(file->objects.size(), 1u);
        const Node& container = file->objects[0];
        EXPECT_EQ(container.type, kTypeContainer);
        ASSERT_EQ(container.children.size(), 2u);
        EXPECT_EQ(file->references.at(1), &container.children[0]);
        DataReader first(*file, container.children[0]);
        const TQ3Point3D p = first.point3D();
        EXPECT_EQ(p.x, 1.0f);
        EXPECT_EQ(p.y, -2.5f);
        EXPECT_EQ(p.z, 3e-3f);
        EXPECT_TRUE(first.atEnd());
        DataReader second(*file, container.children[1]);
        EXPECT_EQ(second.u32(), 4000000000u);
        EXPECT_EQ(second.i32(), -7);
        EXPECT_EQ(second.string(), "a \"quoted\" word");
        EXPECT_TRUE(second.atEnd());
    }
}

TEST(MetafileEncoder, BinaryObjectsAreTypeSizeAndDataInTheFilesByteOrder)
{
    for (Encoding encoding : {Encoding::kBinaryBig, Encoding::kBinaryLittle}) {
        const bool little = encoding == Encoding::kBinaryLittle;
        Encoder out(encoding);
        out.begin(kPointType, "Point");
        out.point3D({1, -2.5f, 3e-3f});
        out.end();
        const std::vector<unsigned char> bytes = out.finish(kQ3FileModeNormal, {});
        BinaryWriter expected(little);
        expected.header();
        expected.object(kPointType, 12);
        expected.f32(1);
        expected.f32(-2.5f);
        expected.f32(3e-3f);
        EXPECT_EQ(bytes, expected.bytes()) << (little ? "little" : "big");
    }
}

// ---- References read by io::ReadContext (the classes' own readers) ----------------------

class ReadContextTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_EQ(Q3Initialize(), kQ3Success); }
    void TearDown() override { Q3Exit(); }
};

std::unique_ptr<Metafile> parseClasses(const std::string& text)
{
    return parse(bytesOf(text), typeOfName);
}

// A binary file: a point (1, 2, 3) at byte 24, a Reference to ID 1 twice, a
// reference to ID `dangling`, and a table of contents giving ID 1 to the
// point.
std::vector<unsigned char> fileWithReferences(bool little, std::uint32_t dangling)
{
    std::vector<unsigned char> out;
    auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            out.push_back(static_cast<unsigned char>(v >> (little ? 8 * i : 24 - 8 * i)));
    };
    auto u64 = [&](std::uint64_t v) {
        u32(static_cast<std::uint32_t>(little ? v : v >> 32));
        u32(static_cast<std::uint32_t>(little ? v >> 32 : v));
    };
    auto f32 = [&](float f) {
        std::uint32_t bits;
        std::memcpy(&bits, &f, 4);
        u32(bits);
    };
    const std::uint64_t toc = 24 + 20 + 3 * 12;
    u32(Q3_OBJECT_TYPE('3', 'D', 'M', 'F'));
    u32(16);
    u32(little ? (6u << 16 | 1u) : (1u << 16 | 6u));
    u32(kQ3FileModeNormal);
    u64(toc);
    u32(kQ3GeometryTypePoint);
    u32(12);
    f32(1);
    f32(2);
    f32(3);
    for (std::uint32_t id : {1u, 1u, dangling}) {
        u32(kTypeReference);
        u32(4);
        u32(id);
    }
    u32(kTypeTableOfContents);
    u32(8 + 4 * 5 + 12);
    u64(0);
    u32(2);  // reference seed
    u32(0);  // type seed
    u32(0);  // entry type 0: ID and location
    u32(12); // entry size
    u32(1);
    u32(1);
    u64(24);
    return out;
}

TEST_F(ReadContextTest, TwoReferencesGiveTheOneObjectTheTableOfContentsNames)
{
    const std::string text = "3DMetafile ( 1 6 Normal toc> )\n"
                             "p: Point ( 1 2 3 )\n"
                             "Reference ( 1 )\nReference ( 1 )\nReference ( 9 )\n"
                             "toc: TableOfContents ( 0 2 0 0 12 1 1 p> )\n";
    std::vector<std::unique_ptr<Metafile>> files;
    files.push_back(parseClasses(text));
    files.push_back(parse(fileWithReferences(false, 9), typeOfName));
    files.push_back(parse(fileWithReferences(true, 9), typeOfName));
    for (const auto& file : files) {
        SCOPED_TRACE(int(file->encoding));
        ASSERT_EQ(file->objects.size(), 4u);
        ReadContext context(*file);
        const Ref<SharedObject> first = context.object(file->objects[1]);
        const Ref<SharedObject> second = context.object(file->objects[2]);
        const Ref<SharedObject> direct = context.object(file->objects[0]);
        ASSERT_TRUE(first);
        EXPECT_TRUE(first->isType(kQ3GeometryTypePoint));
        EXPECT_EQ(first.get(), second.get()); // read once, shared
        EXPECT_EQ(first.get(), direct.get());
        EXPECT_EQ(context.refIdOf(*first), 1u);
        TQ3PointData data{};
        ASSERT_EQ(Q3Point_GetData(static_cast<TQ3GeometryObject>(static_cast<Object*>(first.get())), &data),
                  kQ3Success);
        EXPECT_EQ(data.point.x, 1.0f);
        EXPECT_EQ(data.point.z, 3.0f);
        Q3Point_EmptyData(&data);
        // A reference to an ID no table of contents gives.
        EXPECT_EQ(codeOf([&] { context.object(file->objects[3]); }), kQ3ErrorInvalidMetafileObject);
    }
}

TEST_F(ReadContextTest, AnObjectWithoutAnEntryHasNoReferenceId)
{
    const auto file = parseClasses("3DMetafile ( 1 6 Normal )\nPoint ( 1 2 3 )\n");
    ReadContext context(*file);
    const Ref<SharedObject> point = context.object(file->objects[0]);
    ASSERT_TRUE(point);
    EXPECT_EQ(context.refIdOf(*point), 0u);
}

} // namespace
