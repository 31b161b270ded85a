// The system model's part of the run report and its summary line.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "systemc/core/machine.hpp"
#include "systemc/core/system.hpp"

namespace cube4::tb {

nlohmann::json describe_system(const sysc::SystemResult& r, const sysc::SystemConfig& cfg, double clock_mhz,
                               double wall_seconds, const std::string& check_failure);
void print_system_summary(const sysc::SystemResult& r, const sysc::SystemConfig& cfg, double clock_mhz);

}  // namespace cube4::tb
