// The host interface's programmable state: identification, precision,
// view, mode, cropping, cut plane, shading, volume dimensions and the table
// windows, decoded word by word (docs/registers.md). No SystemC and no
// backend here: control, status, the volume and the base plane are the
// HostInterface's, because they act on the system model.
#pragma once
#include <array>
#include <cstdint>

#include "golden/registers.hpp"
#include "systemc/host/register_map.hpp"

namespace cube4::sysc {

// Throws std::invalid_argument naming the parameter when the map cannot hold it.
void check_hardware_params(const HardwareParams& hw);

class RegisterFile {
 public:
  explicit RegisterFile(const HardwareParams& hw);

  // Every writable register and table entry to its reset value.
  void reset();

  // Word accesses at 4-byte aligned addresses in register space (outside the
  // control block) and in the table windows. check_write says why a write
  // would be refused (None: it would be taken); write() assumes None.
  regmap::ErrorCode check_write(uint64_t addr, uint32_t value) const;
  void write(uint64_t addr, uint32_t value);
  regmap::ErrorCode read(uint64_t addr, uint32_t& value) const;

  // The first 64-bit register holding a value its hardware field cannot
  // take, or nullptr. Its two words are written apart, so only START, which
  // sees both, can check it.
  const regmap::Register* wide_value_out_of_range() const;

  // Bytes of a window the hardware holds (the rest of the window is unmapped).
  uint64_t table_bytes(regmap::Region r) const;

  // What the register file holds. A table is included only when the mode
  // bits say the pipeline uses it (classification: always), as program_host
  // leaves unused tables empty.
  golden::Registers decoded() const;
  // Subvolume k's dimensions (0 0 0 until its VOL_DIM is written).
  std::array<int, 3> volume_dims(int k) const { return values_.vol_dims[static_cast<size_t>(k)]; }
  int vol_index() const { return values_.vol_index; }
  int vol_select() const { return values_.vol_select; }
  std::array<int, 3> slab_origin() const { return values_.slab_origin; }
  std::array<int, 3> slab_size() const { return values_.slab_size; }
  bool poly_enable() const { return values_.poly_enable; }
  std::array<int, 3> poly_size() const { return values_.poly_size; }
  const HardwareParams& hardware() const { return hw_; }

 private:
  regmap::ErrorCode check_register(uint64_t addr, uint32_t value) const;
  regmap::ErrorCode check_table(regmap::Region r, uint64_t addr, uint32_t value) const;
  void write_register(uint64_t addr, uint32_t value);
  bool read_register(uint64_t addr, uint32_t& value) const;

  HardwareParams hw_;
  regmap::RegisterValues values_;      // tables always at full size
};

}  // namespace cube4::sysc
