// The run report (--report FILE.json) and the `info` summary.
#pragma once
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "golden/host_driver.hpp"
#include "golden/perspective_dataflow.hpp"
#include "golden/renderers.hpp"

namespace cube4::tb {

// FNV-1a, 64 bit: identifies a base plane's exact values in reports.
uint64_t fnv1a64(const void* data, size_t bytes);
std::string hex64(uint64_t v);

nlohmann::json describe_volume(const golden::Volume& v);
nlohmann::json describe_view(const golden::Scene& s, const golden::HostProgram& h);
nlohmann::json describe_registers(const golden::Registers& r);
// A perspective frame's offsets in the rings' dataflow (golden/perspective_dataflow.hpp).
nlohmann::json describe_perspective_dataflow(const golden::PerspectiveReach& r);

// Writes `text` (or `j`) to `path` (tb/output_files.hpp gives a temporary),
// checking every write and the close; throws InputError naming `shown_as`.
void write_text(const std::string& path, const std::string& text, const std::string& shown_as = "");
void write_json(const std::string& path, const nlohmann::json& j, const std::string& shown_as = "");

}  // namespace cube4::tb
