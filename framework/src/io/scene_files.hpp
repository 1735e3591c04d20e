#pragma once
// Every file assimp opens for one scene goes through here (issue 35):
// - files the scene names (an OBJ's mtllib, glTF buffers) must lie in its
//   folder or below; others are refused unread, so nothing of them reaches
//   assimp's messages (an mtllib of ../../etc/passwd echoed a line of it),
//   and load_scene then refuses the scene, naming it;
// - the scene file itself can be served from memory: the text with its
//   positions moved home in double (far_positions.hpp).
// Internal to scene_io.cpp.
#include "confined_path.hpp"

#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <filesystem>
#include <string>

namespace hilight {

class SceneFiles : public Assimp::DefaultIOSystem {
public:
  /// `main`: the scene file; `text`: what to serve for it (empty: the file).
  SceneFiles(std::filesystem::path main, std::string text) : m_main(std::move(main)), m_text(std::move(text)) {}

  bool Exists(const char* file) const override {
    // Said to exist, so that the importer opens it and Open refuses it by name.
    if (!inside_folder(m_main.parent_path(), file)) return true;
    return DefaultIOSystem::Exists(file);
  }

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (!inside_folder(m_main.parent_path(), file)) {
      if (m_outside.empty()) m_outside = file;
      return nullptr;
    }
    std::error_code ec;
    if (!m_text.empty() && std::filesystem::equivalent(file, m_main, ec))
      return new Assimp::MemoryIOStream(reinterpret_cast<const uint8_t*>(m_text.data()), m_text.size(), false);
    return DefaultIOSystem::Open(file, mode);
  }

  /// The first file the scene named outside its folder, relative to the
  /// folder ("" when none).
  std::string outside() const { return m_outside.empty() ? "" : named_from(m_main.parent_path(), m_outside); }

private:
  std::filesystem::path m_main;
  std::string m_text;
  std::string m_outside;
};

} // namespace hilight
