#include "minecraft/nbt.h"

#include <bit>
#include <cstring>

#include "core/error.h"

namespace terrasol::nbt {

const Tag* Tag::find(std::string_view name) const {
  if (type_ != TagType::Compound) return nullptr;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return &items_[i];
  }
  return nullptr;
}

const Tag* Tag::find(std::string_view name, TagType type) const {
  const Tag* tag = find(name);
  return tag && tag->type_ == type ? tag : nullptr;
}

template <typename T>
T swapBytes(T v) {
  if constexpr (sizeof(T) == 4) return static_cast<T>(__builtin_bswap32(static_cast<std::uint32_t>(v)));
  if constexpr (sizeof(T) == 8) return static_cast<T>(__builtin_bswap64(static_cast<std::uint64_t>(v)));
  return v;
}

class Reader {
 public:
  Reader(std::span<const std::uint8_t> data, std::string_view what) : data_(data), what_(what) {}

  Document document() {
    const auto type = static_cast<TagType>(u8());
    if (type != TagType::Compound)
      fail("the root tag is type " + std::to_string(int(type)) + ", not a compound");
    Document doc;
    doc.rootName = string();
    value(doc.root, TagType::Compound, 0);
    return doc;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(std::string(what_) + ": NBT at byte " + std::to_string(pos_) + ": " + message);
  }

  void need(std::uint64_t bytes) const {
    if (bytes > data_.size() - pos_) {
      fail("needs " + std::to_string(bytes) + " bytes, " + std::to_string(data_.size() - pos_) + " left");
    }
  }

  template <typename T>
  T big() {
    need(sizeof(T));
    std::make_unsigned_t<T> raw = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      raw = static_cast<decltype(raw)>((raw << 8) | data_[pos_ + i]);
    pos_ += sizeof(T);
    return static_cast<T>(raw);
  }
  std::uint8_t u8() { return static_cast<std::uint8_t>(big<std::int8_t>()); }

  std::string string() {
    const std::uint16_t length = static_cast<std::uint16_t>(big<std::int16_t>());
    need(length);
    const std::string_view raw(reinterpret_cast<const char*>(data_.data() + pos_), length);
    pos_ += length;
    return fromModifiedUtf8(raw);
  }

  // An array or list count: never negative, and at least `elementBytes` each must still be there.
  std::size_t count(std::size_t elementBytes) {
    const std::int32_t n = big<std::int32_t>();
    if (n < 0) fail("negative length " + std::to_string(n));
    need(static_cast<std::uint64_t>(n) * elementBytes);
    return static_cast<std::size_t>(n);
  }

  // Checked once for its whole length, then swapped in bulk: chunks hold ~100 KiB of light arrays.
  template <typename T>
  void array(std::vector<T>& out) {
    out.resize(count(sizeof(T)));
    const std::size_t bytes = out.size() * sizeof(T);
    std::memcpy(out.data(), data_.data() + pos_, bytes);
    pos_ += bytes;
    if constexpr (sizeof(T) > 1) {
      for (T& v : out) v = swapBytes(v);
    }
  }

  void value(Tag& tag, TagType type, int depth) {
    if (depth > kMaxDepth) fail("nested deeper than " + std::to_string(kMaxDepth));
    tag.type_ = type;
    switch (type) {
      case TagType::Byte:
        tag.integer_ = big<std::int8_t>();
        break;
      case TagType::Short:
        tag.integer_ = big<std::int16_t>();
        break;
      case TagType::Int:
        tag.integer_ = big<std::int32_t>();
        break;
      case TagType::Long:
        tag.integer_ = big<std::int64_t>();
        break;
      case TagType::Float:
        tag.real_ = std::bit_cast<float>(big<std::int32_t>());
        break;
      case TagType::Double:
        tag.real_ = std::bit_cast<double>(big<std::int64_t>());
        break;
      case TagType::ByteArray:
        array(tag.bytes_);
        break;
      case TagType::String:
        tag.string_ = string();
        break;
      case TagType::IntArray:
        array(tag.ints_);
        break;
      case TagType::LongArray:
        array(tag.longs_);
        break;
      case TagType::List:
        list(tag, depth);
        break;
      case TagType::Compound:
        compound(tag, depth);
        break;
      default:
        fail("unknown tag type " + std::to_string(int(type)));
    }
  }

  void list(Tag& tag, int depth) {
    tag.listType_ = static_cast<TagType>(u8());
    if (tag.listType_ > TagType::LongArray)
      fail("list of unknown tag type " + std::to_string(int(tag.listType_)));
    // Every element takes a byte at least, except End, which Minecraft writes for empty lists only.
    const std::size_t n = count(tag.listType_ == TagType::End ? 0 : 1);
    if (tag.listType_ == TagType::End && n > 0) fail("list of " + std::to_string(n) + " End tags");
    tag.items_.resize(n);
    for (Tag& item : tag.items_) value(item, tag.listType_, depth + 1);
  }

  void compound(Tag& tag, int depth) {
    for (;;) {
      const auto type = static_cast<TagType>(u8());
      if (type == TagType::End) return;
      tag.names_.push_back(string());
      value(tag.items_.emplace_back(), type, depth + 1);
    }
  }

  std::span<const std::uint8_t> data_;
  std::string_view what_;
  std::size_t pos_ = 0;
};

Document parse(std::span<const std::uint8_t> data, std::string_view what) {
  return Reader(data, what).document();
}

namespace {

void appendUtf8(std::string& out, std::uint32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

}  // namespace

std::string fromModifiedUtf8(std::string_view in) {
  // Block names are ASCII: pass them through untouched.
  bool ascii = true;
  for (const char c : in) ascii &= static_cast<unsigned char>(c) < 0x80;
  if (ascii) return std::string(in);

  constexpr std::uint32_t kReplacement = 0xFFFD;
  // Decodes one UTF-16 unit (1 to 3 bytes) at `i`, or kReplacement for a malformed one.
  const auto unit = [&](std::size_t& i) -> std::uint32_t {
    const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(in[k]); };
    const std::uint8_t b = byte(i++);
    if (b < 0x80) return b;
    const auto continuation = [&](std::size_t k) { return k < in.size() && (byte(k) & 0xC0) == 0x80; };
    if ((b & 0xE0) == 0xC0 && continuation(i)) return ((b & 0x1Fu) << 6) | (byte(i++) & 0x3Fu);
    if ((b & 0xF0) == 0xE0 && continuation(i) && continuation(i + 1)) {
      const std::uint32_t c = ((b & 0x0Fu) << 12) | ((byte(i) & 0x3Fu) << 6) | (byte(i + 1) & 0x3Fu);
      i += 2;
      return c;
    }
    return kReplacement;
  };
  std::string out;
  out.reserve(in.size());
  for (std::size_t i = 0; i < in.size();) {
    std::uint32_t c = unit(i);
    if (c >= 0xD800 && c < 0xDC00) {  // a high surrogate: its low half follows
      std::size_t next = i;
      const std::uint32_t low = next < in.size() ? unit(next) : 0;
      if (low >= 0xDC00 && low < 0xE000) {
        c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
        i = next;
      } else {
        c = kReplacement;
      }
    } else if (c >= 0xDC00 && c < 0xE000) {
      c = kReplacement;
    }
    appendUtf8(out, c);
  }
  return out;
}

}  // namespace terrasol::nbt
