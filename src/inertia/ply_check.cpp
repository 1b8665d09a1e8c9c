#include "ply_check.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::inertia::detail {
namespace {

enum class Scalar { i8, u8, i16, u16, i32, u32, f32, f64 };

std::optional<Scalar> scalar_of(const std::string& name) {
  if (name == "char" || name == "int8") return Scalar::i8;
  if (name == "uchar" || name == "uint8") return Scalar::u8;
  if (name == "short" || name == "int16") return Scalar::i16;
  if (name == "ushort" || name == "uint16") return Scalar::u16;
  if (name == "int" || name == "int32") return Scalar::i32;
  if (name == "uint" || name == "uint32") return Scalar::u32;
  if (name == "float" || name == "float32") return Scalar::f32;
  if (name == "double" || name == "float64") return Scalar::f64;
  return std::nullopt;
}

std::size_t size_of(Scalar s) {
  switch (s) {
    case Scalar::i8:
    case Scalar::u8:
      return 1;
    case Scalar::i16:
    case Scalar::u16:
      return 2;
    case Scalar::i32:
    case Scalar::u32:
    case Scalar::f32:
      return 4;
    case Scalar::f64:
      return 8;
  }
  return 8;
}

/// The value of `s` stored in `bytes` (little-endian when `little`), as a double (exact for every type).
double decode(Scalar s, const unsigned char* bytes, bool little) {
  unsigned char b[8];
  const std::size_t n = size_of(s);
  std::memcpy(b, bytes, n);
  if (little != (std::endian::native == std::endian::little)) std::reverse(b, b + n);
  switch (s) {
    case Scalar::i8:
      return static_cast<double>(static_cast<std::int8_t>(b[0]));
    case Scalar::u8:
      return static_cast<double>(b[0]);
    case Scalar::i16: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Scalar::u16: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Scalar::i32: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Scalar::u32: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Scalar::f32: {
      float v;
      std::memcpy(&v, b, 4);
      return static_cast<double>(v);
    }
    case Scalar::f64: {
      double v;
      std::memcpy(&v, b, 8);
      return v;
    }
  }
  return 0.0;
}

struct Property {
  bool list = false;
  Scalar count_type = Scalar::u8;  // list only
  Scalar type = Scalar::f32;
};

struct Element {
  std::string name;
  unsigned long long count = 0;
  std::vector<Property> properties;
};

enum class Format { ascii, binary_little_endian, binary_big_endian };

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  unsigned long long body_offset = 0;  // bytes from the start of the file
};

/// The header (see ply_check.hpp); `file_bytes` bounds the element counts.
Header read_header(const std::string& path, unsigned long long file_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string text(65536, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  const auto fail = [&](const std::string& why) {
    throw InvalidInput(
        fmt::format("mesh: \"{}\": PLY header line {}: {}; expected a PLY header ending in end_header", path,
                    number, why));
  };
  Header h;
  while (std::getline(lines, line)) {
    ++number;
    h.body_offset += line.size() + (lines.eof() ? 0 : 1);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // A header is plain text: a control character other than a tab (a vertical tab after end_header, found
    // by fuzzing) makes assimp's ASCII reader loop forever.
    const auto control = std::find_if(
        line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 && c != '\t'; });
    if (control != line.end())
      fail(fmt::format("control character 0x{:02x}", static_cast<unsigned char>(*control)));
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;)
      w.push_back(word);
    if (number == 1) {
      if (w.size() != 1 || w[0] != "ply") fail("not \"ply\"");
      continue;
    }
    if (w.empty()) fail("empty");
    const std::string& k = w[0];
    if (k == "end_header") {
      if (w.size() != 1) fail("text after end_header");
      return h;
    }
    if (k == "comment" || k == "obj_info") continue;
    if (k == "format" && w.size() == 3 &&
        (w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian")) {
      h.format = w[1] == "ascii"                  ? Format::ascii
                 : w[1] == "binary_little_endian" ? Format::binary_little_endian
                                                  : Format::binary_big_endian;
    } else if (k == "element" && w.size() == 3 && !w[2].empty() && w[2].size() <= 18 &&
               w[2].find_first_not_of("0123456789") == std::string::npos) {
      // Every element instance takes at least one byte: a count above the file's size is refused before
      // assimp allocates for it (found by fuzzing: 3·10^8 faces declared in a 200-byte file).
      const unsigned long long count = std::stoull(w[2]);
      if (count > file_bytes)
        fail(fmt::format("element {} of {} in a file of {} bytes", w[1].substr(0, 30), count, file_bytes));
      h.elements.push_back(Element{w[1].substr(0, 30), count, {}});
    } else if (k == "property" && (w.size() == 3 || (w.size() == 5 && w[1] == "list"))) {
      Property p;
      p.list = w.size() == 5;
      const auto count_type = p.list ? scalar_of(w[2]) : std::optional<Scalar>(Scalar::u8);
      const auto type = scalar_of(w[p.list ? 3 : 1]);
      if (!count_type || !type) {
        fail(
            fmt::format("property type \"{}\" unknown (char uchar short ushort int uint float double, or "
                        "int8 ... float64 expected)",
                        (!count_type ? w[2] : w[p.list ? 3 : 1]).substr(0, 20)));
      }
      p.count_type = *count_type;
      p.type = *type;
      if (!h.elements.empty()) h.elements.back().properties.push_back(p);
    } else {
      fail("malformed " + k.substr(0, 20));
    }
  }
  ++number;
  fail("no end_header");
  return h;  // not reached
}

/// Reads a file forward from an offset in blocks of 1 MiB.
class BlockReader {
 public:
  BlockReader(const std::string& path, unsigned long long offset, unsigned long long file_bytes)
      : in_(path, std::ios::binary), offset_(offset), file_bytes_(file_bytes) {
    in_.seekg(static_cast<std::streamoff>(offset));
  }
  /// Bytes from the current position to the end of the file.
  unsigned long long left() const { return file_bytes_ > offset_ ? file_bytes_ - offset_ : 0; }
  /// The next `n` <= 8 bytes into `out`; false when the file ends first.
  bool read(unsigned char* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      const int c = get();
      if (c < 0) return false;
      out[i] = static_cast<unsigned char>(c);
    }
    return true;
  }
  /// Skips `n` bytes, which the caller has checked against left().
  void skip(unsigned long long n) {
    const unsigned long long buffered = end_ - pos_;
    if (n <= buffered) {
      pos_ += static_cast<std::size_t>(n);
    } else {
      in_.seekg(static_cast<std::streamoff>(n - buffered), std::ios::cur);
      pos_ = end_ = 0;
    }
    offset_ += n;
  }
  /// The next byte, or -1 at the end of the file.
  int get() {
    if (pos_ == end_) {
      in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
      end_ = static_cast<std::size_t>(in_.gcount());
      pos_ = 0;
      if (end_ == 0) return -1;
    }
    ++offset_;
    return static_cast<unsigned char>(buffer_[pos_++]);
  }

 private:
  std::ifstream in_;
  std::vector<char> buffer_ = std::vector<char>(std::size_t{1} << 20);
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  unsigned long long offset_;
  unsigned long long file_bytes_;
};

[[noreturn]] void refuse_list(const std::string& path, const Element& e, unsigned long long instance,
                              double count, unsigned long long left, const char* unit) {
  throw InvalidInput(fmt::format(
      "mesh: \"{}\": PLY element {} {} declares a list of {} values with {} bytes left in the file; expected "
      "a whole number of values that the file can hold (at most one per {})",
      path, e.name, instance, count, left, unit));
}

void check_binary_body(const std::string& path, const Header& h, unsigned long long file_bytes) {
  BlockReader r(path, h.body_offset, file_bytes);
  const bool little = h.format == Format::binary_little_endian;
  for (const Element& e : h.elements) {
    const auto ends = [&](unsigned long long instance) {
      throw InvalidInput(fmt::format(
          "mesh: \"{}\": PLY body ends inside element {} {} (the header declares {}); expected the values "
          "the header declares",
          path, e.name, instance, e.count));
    };
    if (e.properties.empty()) continue;
    if (std::none_of(e.properties.begin(), e.properties.end(), [](const Property& p) { return p.list; })) {
      unsigned long long stride = 0;
      for (const Property& p : e.properties)
        stride += size_of(p.type);
      // count <= file size (header check) and stride <= 8 per property: no overflow.
      if (e.count * stride > r.left()) ends(r.left() / stride);
      r.skip(e.count * stride);
      continue;
    }
    for (unsigned long long i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        if (!p.list) {
          if (size_of(p.type) > r.left()) ends(i);
          r.skip(size_of(p.type));
          continue;
        }
        unsigned char bytes[8];
        if (!r.read(bytes, size_of(p.count_type))) ends(i);
        const double n = decode(p.count_type, bytes, little);
        const double item = static_cast<double>(size_of(p.type));
        if (!(n >= 0.0) || n != std::floor(n) || n * item > static_cast<double>(r.left()))
          refuse_list(path, e, i, n, r.left(), fmt::format("{} bytes", size_of(p.type)).c_str());
        r.skip(static_cast<unsigned long long>(n) * size_of(p.type));
      }
    }
  }
}

void check_ascii_body(const std::string& path, const Header& h, unsigned long long file_bytes) {
  BlockReader r(path, h.body_offset, file_bytes);
  // The next white-space separated token (at most 64 characters; a longer one is returned cut, which is not
  // a number); empty at the end of the file.
  const auto token = [&r] {
    std::string t;
    int c = r.get();
    while (c >= 0 && std::isspace(c))
      c = r.get();
    while (c >= 0 && !std::isspace(c)) {
      if (t.size() < 64) t.push_back(static_cast<char>(c));
      c = r.get();
    }
    return t;
  };
  for (const Element& e : h.elements) {
    if (e.properties.empty()) continue;
    for (unsigned long long i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        const std::string t = token();
        if (t.empty()) return;  // the body ends early: assimp reports it
        if (!p.list) continue;
        char* end = nullptr;
        const double n = std::strtod(t.c_str(), &end);
        if (end != t.c_str() + t.size() || !std::isfinite(n)) return;  // not a number: assimp reports it
        // After the length and its separator, n values take at least n characters and n - 1 separators.
        if (!(n >= 0.0) || n != std::floor(n) || 2.0 * n - 1.0 > static_cast<double>(r.left()))
          refuse_list(path, e, i, n, r.left(), "2 characters");
        for (double k = 0; k < n; ++k)
          if (token().empty()) return;
      }
    }
  }
}

}  // namespace

void check_ply_file(const std::string& path) {
  std::error_code ec;
  const auto file_bytes = static_cast<unsigned long long>(std::filesystem::file_size(path, ec));
  if (ec) return;  // load_mesh has opened it; a file that vanished since is reported by assimp
  const Header h = read_header(path, file_bytes);
  if (h.format == Format::ascii)
    check_ascii_body(path, h, file_bytes);
  else
    check_binary_body(path, h, file_bytes);
}

}  // namespace poinsot::inertia::detail
