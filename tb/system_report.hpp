// The system model's part of the run report and its summary line.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "golden/blocks.hpp"
#include "systemc/core/machine.hpp"
#include "systemc/core/partitioned.hpp"
#include "systemc/core/system.hpp"

namespace cube4::tb {

nlohmann::json describe_system(const sysc::SystemResult& r, const sysc::SystemConfig& cfg, double clock_mhz,
                               double wall_seconds, const std::string& check_failure);
void print_system_summary(const sysc::SystemResult& r, const sysc::SystemConfig& cfg, double clock_mhz);

// A partitioned render (golden/blocks.hpp): the plan, and the machines and
// composition network that ran it.
nlohmann::json describe_blocks(const golden::BlockPlan& plan);
nlohmann::json describe_partitioned(const sysc::PartitionedResult& r, const sysc::SystemConfig& cfg,
                                    double clock_mhz, double wall_seconds, const std::string& check_failure);
void print_partitioned_summary(const sysc::PartitionedResult& r, const sysc::SystemConfig& cfg, double clock_mhz);

}  // namespace cube4::tb
