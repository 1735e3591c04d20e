#include "hilight/io/ply_reader.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace hilight {

namespace {

enum class Format { Ascii, BinaryLE, BinaryBE };

struct Property {
  std::string name, type;
  bool is_list = false;
  std::string count_type;
};

struct Element {
  std::string name;
  size_t count = 0;
  std::vector<Property> properties;
};

size_t type_size(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

template <class T>
T load(const unsigned char* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

double decode(const std::string& t, const unsigned char* p, bool swap) {
  if (t == "char" || t == "int8") return double(load<int8_t>(p, false));
  if (t == "uchar" || t == "uint8") return double(load<uint8_t>(p, false));
  if (t == "short" || t == "int16") return double(load<int16_t>(p, swap));
  if (t == "ushort" || t == "uint16") return double(load<uint16_t>(p, swap));
  if (t == "int" || t == "int32") return double(load<int32_t>(p, swap));
  if (t == "uint" || t == "uint32") return double(load<uint32_t>(p, swap));
  if (t == "float" || t == "float32") return double(load<float>(p, swap));
  return load<double>(p, swap);
}

} // namespace

PlyVertices read_ply_vertices(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file, std::filesystem::exists(path) ? "cannot open" : "no such file");
  std::string line;
  if (!std::getline(in, line) || line.substr(0, 3) != "ply") throw InputError(file, "not a PLY file (no 'ply' magic)");

  Format format = Format::Ascii;
  std::vector<Element> elements;
  bool has_format = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "end_header") break;
    if (word == "format") {
      std::string f;
      ls >> f;
      if (f == "ascii") format = Format::Ascii;
      else if (f == "binary_little_endian") format = Format::BinaryLE;
      else if (f == "binary_big_endian") format = Format::BinaryBE;
      else throw InputError(file, "unknown PLY format '" + f + "'");
      has_format = true;
    } else if (word == "element") {
      Element e;
      long long count = -1;
      ls >> e.name >> count;
      if (!ls || count < 0) throw InputError(file, "malformed element line '" + line + "'");
      e.count = size_t(count);
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty()) throw InputError(file, "property before any element");
      Property p;
      std::string t;
      ls >> t;
      if (t == "list") {
        p.is_list = true;
        ls >> p.count_type >> p.type >> p.name;
        if (!type_size(p.count_type)) throw InputError(file, "unknown list count type '" + p.count_type + "'");
      } else {
        p.type = t;
        ls >> p.name;
      }
      if (!ls || !type_size(p.type)) throw InputError(file, "malformed property line '" + line + "'");
      elements.back().properties.push_back(p);
    } else if (word != "comment" && word != "obj_info" && !word.empty()) {
      throw InputError(file, "unexpected PLY header line '" + line + "'");
    }
  }
  if (line != "end_header" && line.substr(0, 10) != "end_header") throw InputError(file, "PLY header has no end_header");
  if (!has_format) throw InputError(file, "PLY header has no format line");

  // Counts in the header are claims: never reserve more than the bytes left
  // in the file could hold (a tiny file can claim billions of vertices).
  const std::streampos data_start = in.tellg();
  in.seekg(0, std::ios::end);
  const size_t bytes_left = size_t(in.tellg() - data_start);
  in.seekg(data_start);
  PlyVertices out;
  const bool swap = (format == Format::BinaryBE) == (std::endian::native == std::endian::little);
  for (const Element& e : elements) {
    // Rows of nothing would be read forever (a fuzzed count of 2.5·10¹⁵).
    if (e.count > 0 && e.properties.empty())
      throw InputError(file, "element '" + e.name + "' has " + std::to_string(e.count) + " rows but no properties");
    const bool is_vertex = e.name == "vertex";
    if (is_vertex) {
      out.count = e.count;
      size_t row_bytes = 0;
      for (const auto& p : e.properties) row_bytes += p.is_list ? type_size(p.count_type) : type_size(p.type);
      // ASCII takes at least 2 bytes a value ("0 "), binary its type's size.
      const size_t min_row = format == Format::Ascii ? 2 * e.properties.size() : row_bytes;
      // (+1: the file's very last value needs no separator after it.)
      if (min_row > 0 && e.count > (bytes_left + 1) / min_row)
        throw InputError(file, "the header claims " + std::to_string(e.count) + " vertices, more than the file's " +
                                   std::to_string(bytes_left) + " bytes of data can hold");
      for (const auto& p : e.properties)
        if (!p.is_list) {
          out.properties[p.name].reserve(e.count);
          out.types[p.name] = p.type;
        }
    }
    for (size_t i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        auto truncated = [&] {
          return InputError(file, "file ends inside element '" + e.name + "' " + std::to_string(i) + " of " + std::to_string(e.count));
        };
        if (format == Format::Ascii) {
          std::string token;
          size_t n = 1;
          if (p.is_list) {
            if (!(in >> token)) throw truncated();
            char* end = nullptr;
            errno = 0;
            unsigned long long count = std::strtoull(token.c_str(), &end, 10);
            if (token.empty() || *end != '\0' || token[0] == '-' || errno == ERANGE || count > bytes_left)
              throw InputError(file, "element '" + e.name + "' " + std::to_string(i) + ": list length '" + token + "' is not valid");
            n = size_t(count);
          }
          for (size_t k = 0; k < n; ++k) {
            if (!(in >> token)) throw truncated();
            if (is_vertex && !p.is_list) {
              char* end = nullptr;
              double v = std::strtod(token.c_str(), &end);
              if (*end != '\0') throw InputError(file, "vertex " + std::to_string(i) + ": '" + token + "' is not a number");
              out.properties[p.name].push_back(v);
            }
          }
        } else {
          unsigned char buf[8];
          size_t n = 1;
          if (p.is_list) {
            if (!in.read(reinterpret_cast<char*>(buf), std::streamsize(type_size(p.count_type)))) throw truncated();
            double count = decode(p.count_type, buf, swap);
            if (!(count >= 0) || count > double(bytes_left))
              throw InputError(file, "element '" + e.name + "' " + std::to_string(i) + ": list length " + std::to_string(count) + " is not valid");
            n = size_t(count);
          }
          size_t sz = type_size(p.type);
          for (size_t k = 0; k < n; ++k) {
            if (!in.read(reinterpret_cast<char*>(buf), std::streamsize(sz))) throw truncated();
            if (is_vertex && !p.is_list) out.properties[p.name].push_back(decode(p.type, buf, swap));
          }
        }
      }
    }
    if (is_vertex) break;  // later elements (faces) are not needed
  }
  return out;
}

} // namespace hilight
