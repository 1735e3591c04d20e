#pragma once
/// A general PLY reader: ascii, binary little- and big-endian; every scalar
/// type; lists skipped. Returns the vertex element's scalar properties.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hilight {

struct PlyVertices {
  size_t count = 0;
  /// Property name -> one value per vertex, in file order.
  std::map<std::string, std::vector<double>> properties;
  /// Property name -> its declared type ("float", "uchar", ...).
  std::map<std::string, std::string> types;
  bool has(const std::string& name) const { return properties.count(name) != 0; }
};

/// Throws InputError naming the file on anything malformed or truncated.
PlyVertices read_ply_vertices(const std::filesystem::path& path);

} // namespace hilight
