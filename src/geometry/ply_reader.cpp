// PLY (ASCII, binary little- and big-endian): the header is checked against the file before the
// body is read, and the body is read element by element with every count checked against the
// bytes that remain.
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "mesh_readers.h"
#include "text_scanner.h"
#include "view_direction_classification/common/error.h"

namespace vdc::mesh_readers {
namespace {

// Generous bounds on what a header may declare; a real header has a few lines.
constexpr std::size_t kMaxHeaderBytes = 1 << 20;
constexpr std::size_t kMaxElements = 256;
constexpr std::size_t kMaxPropertiesPerElement = 256;

enum class Encoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

std::optional<Type> typeNamed(std::string_view name) {
  static const std::pair<const char*, Type> kNames[] = {
      {"char", Type::kInt8},      {"int8", Type::kInt8},       {"uchar", Type::kUint8},
      {"uint8", Type::kUint8},    {"short", Type::kInt16},     {"int16", Type::kInt16},
      {"ushort", Type::kUint16},  {"uint16", Type::kUint16},   {"int", Type::kInt32},
      {"int32", Type::kInt32},    {"uint", Type::kUint32},     {"uint32", Type::kUint32},
      {"float", Type::kFloat32},  {"float32", Type::kFloat32}, {"double", Type::kFloat64},
      {"float64", Type::kFloat64}};
  for (const auto& [spelling, type] : kNames) {
    if (name == spelling) return type;
  }
  return std::nullopt;
}

std::size_t sizeOf(Type type) {
  switch (type) {
    case Type::kInt8:
    case Type::kUint8:
      return 1;
    case Type::kInt16:
    case Type::kUint16:
      return 2;
    case Type::kInt32:
    case Type::kUint32:
    case Type::kFloat32:
      return 4;
    case Type::kFloat64:
      return 8;
  }
  return 8;
}

// An integral value read as a double (every PLY integer type fits), for messages.
std::string integerText(double value) {
  if (std::abs(value) < 1e18) return std::to_string(static_cast<std::int64_t>(value));
  std::ostringstream text;
  text << value;
  return text.str();
}

bool isInteger(Type type) { return type != Type::kFloat32 && type != Type::kFloat64; }

struct Property {
  std::string name;
  bool is_list = false;
  Type count_type = Type::kUint8;  // lists only
  Type type = Type::kFloat32;      // the value's, or the list items'
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;

  // The fewest bytes one element takes in a binary body (an empty list takes its count).
  std::size_t minimumBinaryBytes() const {
    std::size_t bytes = 0;
    for (const auto& p : properties) bytes += sizeOf(p.is_list ? p.count_type : p.type);
    return bytes;
  }
};

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  std::size_t body_offset = 0;
  std::size_t lines = 0;  // the header's, end_header included
};

[[noreturn]] void headerError(std::size_t line, const std::string& what) {
  throw Error("header line " + std::to_string(line) + ": " + what);
}

Property parseProperty(const std::vector<std::string_view>& words, std::size_t line) {
  Property property;
  if (words.size() >= 2 && words[1] == "list") {
    if (words.size() != 5) headerError(line, "expected 'property list COUNT_TYPE TYPE NAME'");
    const auto count_type = typeNamed(words[2]);
    const auto type = typeNamed(words[3]);
    if (!count_type || !type) headerError(line, "unknown property type");
    if (!isInteger(*count_type)) headerError(line, "a list's count type must be an integer type");
    property.is_list = true;
    property.count_type = *count_type;
    property.type = *type;
    property.name = std::string(words[4]);
  } else {
    if (words.size() != 3) headerError(line, "expected 'property TYPE NAME'");
    const auto type = typeNamed(words[1]);
    if (!type) headerError(line, "unknown property type '" + std::string(words[1]) + "'");
    property.type = *type;
    property.name = std::string(words[2]);
  }
  return property;
}

Header parseHeader(std::string_view bytes) {
  TextScanner scanner(bytes.substr(0, kMaxHeaderBytes));
  std::string_view line;
  if (!scanner.nextLine(&line) || line != "ply") {
    throw Error("it does not start with the line 'ply'");
  }
  Header header;
  bool have_format = false;
  while (scanner.nextLine(&line)) {
    const std::size_t number = scanner.lineNumber();
    const auto words = splitWords(line, 6);
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (!have_format) headerError(number, "end_header before any 'format' line");
      header.body_offset = scanner.offset();  // just after the line's end
      header.lines = number;
      return header;
    }
    if (keyword == "format") {
      if (words.size() != 3) headerError(number, "expected 'format ENCODING 1.0'");
      if (words[1] == "ascii") {
        header.encoding = Encoding::kAscii;
      } else if (words[1] == "binary_little_endian") {
        header.encoding = Encoding::kBinaryLittleEndian;
      } else if (words[1] == "binary_big_endian") {
        header.encoding = Encoding::kBinaryBigEndian;
      } else {
        headerError(number, "unknown format '" + std::string(words[1]) + "'");
      }
      have_format = true;
    } else if (keyword == "element") {
      std::int64_t count = 0;
      if (words.size() != 3 || !parseInteger(words[2], &count) || count < 0) {
        headerError(number, "expected 'element NAME COUNT' with a count >= 0");
      }
      if (header.elements.size() == kMaxElements) headerError(number, "too many elements");
      for (const auto& element : header.elements) {
        if (element.name == words[1]) {
          headerError(number, "element '" + element.name + "' is declared twice");
        }
      }
      header.elements.push_back({std::string(words[1]), static_cast<std::uint64_t>(count), {}});
    } else if (keyword == "property") {
      if (header.elements.empty()) headerError(number, "a property before any element");
      auto& properties = header.elements.back().properties;
      if (properties.size() == kMaxPropertiesPerElement) headerError(number, "too many properties");
      properties.push_back(parseProperty(words, number));
    } else {
      headerError(number, "unknown keyword '" + std::string(keyword) + "'");
    }
  }
  throw Error(bytes.size() > kMaxHeaderBytes ? "no end_header within the first MiB"
                                             : "the header has no end_header line");
}

// Reads the values of a binary body, checking each read against the end of the bytes.
class BinaryValues {
 public:
  BinaryValues(std::string_view body, bool big_endian) : body_(body), swap_(big_endian) {}

  std::size_t remaining() const { return body_.size() - position_; }
  bool skip(std::size_t bytes) {
    if (bytes > remaining()) return false;
    position_ += bytes;
    return true;
  }
  bool read(Type type, double* value) {
    const std::size_t size = sizeOf(type);
    if (size > remaining()) return false;
    unsigned char raw[8];
    std::memcpy(raw, body_.data() + position_, size);
    position_ += size;
    if (swap_) {
      for (std::size_t i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
    }
    *value = decode(type, raw);
    return true;
  }

 private:
  static double decode(Type type, const unsigned char* raw) {
    switch (type) {
      case Type::kInt8:
        return as<std::int8_t>(raw);
      case Type::kUint8:
        return as<std::uint8_t>(raw);
      case Type::kInt16:
        return as<std::int16_t>(raw);
      case Type::kUint16:
        return as<std::uint16_t>(raw);
      case Type::kInt32:
        return as<std::int32_t>(raw);
      case Type::kUint32:
        return as<std::uint32_t>(raw);
      case Type::kFloat32:
        return as<float>(raw);
      case Type::kFloat64:
        return as<double>(raw);
    }
    return 0.0;
  }
  template <typename T>
  static double as(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return static_cast<double>(value);
  }

  std::string_view body_;
  std::size_t position_ = 0;
  bool swap_;
};

// Reads the values of an ASCII body: whitespace-separated numbers, one element per line by
// convention (not relied on).
class AsciiValues {
 public:
  AsciiValues(std::string_view body, std::size_t header_lines)
      : scanner_(body), header_lines_(header_lines) {}

  bool read(Type type, double* value) {
    std::string_view token;
    if (!scanner_.nextToken(&token)) return false;
    if (!parseReal(token, value)) fail(token, "is not a number");
    // floor(NaN) != NaN, so "nan" is no integer; infinities fail the callers' range checks.
    if (isInteger(type) && std::floor(*value) != *value) fail(token, "is not an integer");
    return true;
  }

 private:
  [[noreturn]] void fail(std::string_view token, const char* what) const {
    throw Error("line " + std::to_string(header_lines_ + scanner_.lineNumber()) + ": " +
                quoted(token) + " " + what);
  }

  TextScanner scanner_;
  std::size_t header_lines_;
};

// What the body reader keeps of the vertex and face elements.
struct Layout {
  const Element* vertex = nullptr;
  int x = -1, y = -1, z = -1;  // property indices in the vertex element
  const Element* face = nullptr;
  int indices = -1;  // the list property of the face element
};

Layout findLayout(const Header& header) {
  Layout layout;
  for (const auto& element : header.elements) {
    if (element.name == "vertex") layout.vertex = &element;
    if (element.name == "face") layout.face = &element;
  }
  if (layout.vertex == nullptr) throw Error("the header declares no 'vertex' element");
  if (layout.vertex->count > static_cast<std::uint64_t>(kMaxVertexIndex)) {
    throw Error("the header declares " + std::to_string(layout.vertex->count) +
                " vertices, more than this loader supports");
  }
  const auto& vertex_properties = layout.vertex->properties;
  for (std::size_t p = 0; p < vertex_properties.size(); ++p) {
    int* slot = vertex_properties[p].name == "x"   ? &layout.x
                : vertex_properties[p].name == "y" ? &layout.y
                : vertex_properties[p].name == "z" ? &layout.z
                                                   : nullptr;
    if (slot == nullptr) continue;
    if (vertex_properties[p].is_list) {
      throw Error("the vertex property '" + vertex_properties[p].name + "' is a list");
    }
    *slot = static_cast<int>(p);
  }
  for (const auto& [index, name] : {std::pair{layout.x, "x"}, {layout.y, "y"}, {layout.z, "z"}}) {
    if (index < 0) throw Error(std::string("the vertex element has no property '") + name + "'");
  }
  if (layout.face != nullptr) {
    const auto& face_properties = layout.face->properties;
    for (std::size_t p = 0; p < face_properties.size(); ++p) {
      const auto& property = face_properties[p];
      if (property.name != "vertex_indices" && property.name != "vertex_index") continue;
      if (!property.is_list || !isInteger(property.type)) {
        throw Error("the face property '" + property.name + "' is not a list of integers");
      }
      layout.indices = static_cast<int>(p);
    }
    if (layout.indices < 0) {
      throw Error("the face element has no 'vertex_indices' list");
    }
  }
  return layout;
}

// Refuses a header that claims more elements than the body can hold, before anything is read
// or allocated: a cut file, or counts no file backs.
void checkCountsAgainstSize(const Header& header, std::size_t body_bytes) {
  for (const auto& element : header.elements) {
    if (element.properties.empty() || element.count == 0) continue;
    // Binary: every element takes its minimum bytes. ASCII: every value is a number followed by
    // a separator, at least two characters (the last may lack its separator).
    const std::uint64_t per_element = header.encoding == Encoding::kAscii
                                          ? 2 * element.properties.size()
                                          : element.minimumBinaryBytes();
    const std::uint64_t slack = header.encoding == Encoding::kAscii ? 1 : 0;
    if (element.count > (body_bytes + slack) / per_element) {
      std::ostringstream message;
      message << "the header declares " << element.count << " " << element.name
              << " elements of at least " << per_element << " bytes each, but the body has "
              << body_bytes << " bytes (a cut file?)";
      throw Error(message.str());
    }
  }
}

template <typename Values>
class BodyReader {
 public:
  BodyReader(const Header& header, const Layout& layout, Values* values)
      : header_(header), layout_(layout), values_(values) {}

  IndexedPolygons read() {
    IndexedPolygons mesh;
    mesh.vertices.reserve(layout_.vertex->count);
    for (const auto& element : header_.elements) {
      if (element.properties.empty()) continue;  // nothing to read, however many there are
      for (std::uint64_t i = 0; i < element.count; ++i) {
        if (&element == layout_.vertex) {
          readVertex(element, i, &mesh);
        } else if (&element == layout_.face) {
          readFace(element, i, &mesh);
        } else {
          skipElement(element, i);
        }
      }
    }
    return mesh;
  }

 private:
  [[noreturn]] void endsEarly(const Element& element, std::uint64_t i) const {
    throw Error("the file ends in " + element.name + " " + std::to_string(i) + " of " +
                std::to_string(element.count) + " (a cut file?)");
  }

  double value(const Element& element, std::uint64_t i, Type type) {
    double v = 0.0;
    if (!values_->read(type, &v)) endsEarly(element, i);
    return v;
  }

  // A list's count, checked before its items are read: at most `limit` (and, binary, no more
  // items than bytes remain).
  std::size_t listCount(const Element& element, std::uint64_t i, const Property& property,
                        std::size_t limit) {
    const double count = value(element, i, property.count_type);
    if (!(count >= 0 && count <= static_cast<double>(limit))) {
      std::string message = element.name + " " + std::to_string(i) + " has a list '" +
                            property.name + "' of " + integerText(count) + " items";
      if (count >= 0) message += ", more than the " + std::to_string(limit) + " supported";
      throw Error(message);
    }
    return static_cast<std::size_t>(count);
  }

  void readVertex(const Element& element, std::uint64_t i, IndexedPolygons* mesh) {
    Eigen::Vector3f position = Eigen::Vector3f::Zero();
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const Property& property = element.properties[p];
      if (property.is_list) {
        skipList(element, i, property);
        continue;
      }
      const double v = value(element, i, property.type);
      const int index = static_cast<int>(p);
      if (index == layout_.x) position.x() = toCoordinate(v);
      if (index == layout_.y) position.y() = toCoordinate(v);
      if (index == layout_.z) position.z() = toCoordinate(v);
    }
    mesh->vertices.push_back(position);
  }

  void readFace(const Element& element, std::uint64_t i, IndexedPolygons* mesh) {
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const Property& property = element.properties[p];
      if (static_cast<int>(p) != layout_.indices) {
        if (property.is_list) {
          skipList(element, i, property);
        } else {
          value(element, i, property.type);
        }
        continue;
      }
      const std::size_t count = listCount(element, i, property, kMaxPolygonCorners);
      corners_.clear();
      for (std::size_t k = 0; k < count; ++k) {
        const double index = value(element, i, property.type);
        if (!(index >= 0 && index <= static_cast<double>(kMaxVertexIndex))) {
          throw Error("face " + std::to_string(i) + " refers to vertex " + integerText(index));
        }
        corners_.push_back(static_cast<std::int32_t>(index));
      }
      mesh->addPolygon(corners_.data(), corners_.size());
    }
  }

  void skipList(const Element& element, std::uint64_t i, const Property& property) {
    const std::size_t count =
        listCount(element, i, property, std::numeric_limits<std::uint32_t>::max());
    for (std::size_t k = 0; k < count; ++k) value(element, i, property.type);
  }

  void skipElement(const Element& element, std::uint64_t i) {
    for (const auto& property : element.properties) {
      if (property.is_list) {
        skipList(element, i, property);
      } else {
        value(element, i, property.type);
      }
    }
  }

  const Header& header_;
  const Layout& layout_;
  Values* values_;
  std::vector<std::int32_t> corners_;
};

}  // namespace

IndexedPolygons readPly(std::string_view bytes) {
  const Header header = parseHeader(bytes);
  const Layout layout = findLayout(header);
  const std::string_view body = bytes.substr(header.body_offset);
  checkCountsAgainstSize(header, body.size());
  if (header.encoding == Encoding::kAscii) {
    AsciiValues values(body, header.lines);
    return BodyReader<AsciiValues>(header, layout, &values).read();
  }
  BinaryValues values(body, header.encoding == Encoding::kBinaryBigEndian);
  return BodyReader<BinaryValues>(header, layout, &values).read();
}

}  // namespace vdc::mesh_readers
