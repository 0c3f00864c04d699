#pragma once
// Minecraft's Named Binary Tag format, read-only: big-endian, strings in Java's modified UTF-8, one
// named root compound. Every length is checked against the bytes left before anything is allocated,
// and nesting is limited, so a hostile file costs at most its own size: a claimed 2 GiB array in a
// 4 KiB chunk, or compounds nested 10 000 deep, are errors, not allocations or stack overflows.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace terrasol::nbt {

enum class TagType : std::uint8_t {
  End = 0,
  Byte = 1,
  Short = 2,
  Int = 3,
  Long = 4,
  Float = 5,
  Double = 6,
  ByteArray = 7,
  String = 8,
  List = 9,
  Compound = 10,
  IntArray = 11,
  LongArray = 12,
};

// Minecraft refuses deeper trees (NbtAccounter's 512); chunks nest about 6 deep.
inline constexpr int kMaxDepth = 512;

// One tag. Numbers of every width are kept as int64/double; arrays as their own element type.
class Tag {
 public:
  TagType type() const { return type_; }

  // A compound's member, or null when absent (or this is not a compound).
  const Tag* find(std::string_view name) const;
  // The member when it has `type`, else null.
  const Tag* find(std::string_view name, TagType type) const;

  bool isInteger() const { return type_ >= TagType::Byte && type_ <= TagType::Long; }
  std::int64_t integer() const { return integer_; }  // Byte, Short, Int, Long
  double real() const { return real_; }              // Float, Double
  const std::string& string() const { return string_; }
  std::span<const std::int8_t> bytes() const { return bytes_; }
  std::span<const std::int32_t> ints() const { return ints_; }
  std::span<const std::int64_t> longs() const { return longs_; }
  // A list's items, or a compound's member values (names in memberNames()).
  const std::vector<Tag>& items() const { return items_; }
  const std::vector<std::string>& memberNames() const { return names_; }
  TagType listType() const { return listType_; }

 private:
  friend class Reader;
  TagType type_ = TagType::End;
  TagType listType_ = TagType::End;
  std::int64_t integer_ = 0;
  double real_ = 0;
  std::string string_;
  std::vector<std::int8_t> bytes_;
  std::vector<std::int32_t> ints_;
  std::vector<std::int64_t> longs_;
  std::vector<Tag> items_;
  std::vector<std::string> names_;
};

struct Document {
  std::string rootName;
  Tag root;  // a compound
};

// Parses a whole uncompressed NBT document. Throws terrasol::Error saying what is wrong and at which
// byte; `what` names the source ("r.0.0.mca chunk (3, 4)") in that message.
Document parse(std::span<const std::uint8_t> data, std::string_view what);

// Java's modified UTF-8 to standard UTF-8: U+0000 comes as C0 80 and characters beyond the BMP as
// two three-byte surrogates. Malformed sequences become U+FFFD.
std::string fromModifiedUtf8(std::string_view in);

}  // namespace terrasol::nbt
