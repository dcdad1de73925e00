// The frames between an instance and its process (Protocol.hpp): what one
// side writes the other reads back, with its sequence number; bytes that
// are not a frame, a frame longer than any, and a stream that ends within
// a frame are named as such, not misread or waited for.
#include "Protocol.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

using fmuImport::protocol::FrameReader;
using fmuImport::protocol::FrameWriter;
using fmuImport::protocol::Garbled;
using fmuImport::protocol::Inbox;

std::vector<char> twoFrames()
{
    std::vector<char> bytes;
    FrameWriter(bytes, 7)
        .put(std::int32_t(-3))
        .put(std::string("spring"))
        .finish();
    FrameWriter(bytes, 8).put(std::vector<double> {0.5, 1e300}).finish();
    return bytes;
}

// The message of the Garbled that reading bytes throws; "" when none
std::string garbledReading(const std::vector<char>& bytes)
{
    Inbox inbox;
    inbox.append(bytes.data(), bytes.size());
    FrameReader frame(nullptr, nullptr);
    std::uint64_t seq = 0;
    try {
        while (inbox.next(frame, seq)) { }
    } catch (const Garbled& e) {
        return e.what();
    }
    return "";
}

TEST(Protocol, FramesComeBackWithTheirSequenceNumbers)
{
    const std::vector<char> bytes = twoFrames();
    Inbox inbox;
    FrameReader frame(nullptr, nullptr);
    std::uint64_t seq = 0;
    // Byte by byte: a frame is complete once all its bytes are in
    std::vector<std::uint64_t> seqs;
    for (const char b : bytes) {
        inbox.append(&b, 1);
        while (inbox.next(frame, seq)) {
            seqs.push_back(seq);
            if (seq == 7) {
                EXPECT_EQ(frame.get<std::int32_t>(), -3);
                EXPECT_EQ(frame.getString(), "spring");
            } else {
                EXPECT_EQ(frame.getVector<double>(),
                          (std::vector<double> {0.5, 1e300}));
            }
        }
    }
    EXPECT_EQ(seqs, (std::vector<std::uint64_t> {7, 8}));
    EXPECT_EQ(inbox.pending(), 0u);
}

TEST(Protocol, StrayBytesAreNamedAtOnce)
{
    // Shorter than a frame's header: named, not awaited as a frame's start
    const std::string stray = "stray bytes!";
    EXPECT_EQ(garbledReading(std::vector<char>(stray.begin(), stray.end())),
              "carried stray bytes (12 bytes that are not a message: magic "
              "word 0x61727473 where a message begins with 0x31554d46)");
    // After a frame: the frame is read, the bytes after it are named
    std::vector<char> bytes = twoFrames();
    bytes.insert(bytes.end(), stray.begin(), stray.begin() + 4);
    EXPECT_EQ(garbledReading(bytes),
              "carried stray bytes (4 bytes that are not a message: magic "
              "word 0x61727473 where a message begins with 0x31554d46)");
}

TEST(Protocol, LengthLongerThanAnyIsNamed)
{
    std::vector<char> bytes = twoFrames();
    const std::uint32_t huge = 0xfffffff0u;
    std::memcpy(bytes.data() + 4, &huge, sizeof huge);
    EXPECT_EQ(garbledReading(bytes),
              "carried stray bytes (a message of 4294967280 bytes, longer than "
              "any: at most 1073741824)");
}

TEST(Protocol, StreamEndingWithinAFrameIsNamed)
{
    const std::vector<char> bytes = twoFrames();
    Inbox inbox;
    FrameReader frame(nullptr, nullptr);
    std::uint64_t seq = 0;
    inbox.append(bytes.data(), 10);
    EXPECT_FALSE(inbox.next(frame, seq));
    EXPECT_EQ(std::string(inbox.cutShort().what()),
              "ended within a message (10 of its 16-byte header)");
    inbox.append(bytes.data() + 10, 20);
    EXPECT_FALSE(inbox.next(frame, seq));
    EXPECT_EQ(std::string(inbox.cutShort().what()),
              "ended within a message (30 of its 34 bytes)");
}

TEST(Protocol, ShortBodyThrows)
{
    std::vector<char> bytes;
    FrameWriter(bytes, 1).put(std::uint8_t(1)).finish();
    Inbox inbox;
    inbox.append(bytes.data(), bytes.size());
    FrameReader frame(nullptr, nullptr);
    std::uint64_t seq = 0;
    ASSERT_TRUE(inbox.next(frame, seq));
    EXPECT_THROW(frame.get<double>(), fmuImport::Error);
}

} // namespace
