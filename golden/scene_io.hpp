// Scenes from JSON (schema: docs/scene.md). Unknown keys and out-of-range
// values are InputErrors that name the file, the key path and the value.
#pragma once
#include <string>

#include "golden/scene.hpp"

namespace cube4::golden {

Scene parse_scene(const std::string& json_text, const std::string& file_name);
Scene load_scene(const std::string& path);
Scene default_scene();  // shaded composite of brainsmall
// Fills in the defaults that depend on other fields (transfer functions,
// lights, GmLUT) and checks cross-field constraints. parse_scene calls it.
void finish_scene(Scene& s);

}  // namespace cube4::golden
