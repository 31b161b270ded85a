# CUBE4_SYSTEM_WIDTHS: the widths the system model's RTL is verilated with
# (docs/system.md, "RTL at other widths"). A list of Verilog parameter
# overrides, each a width of golden/precision.hpp's kPrecisionFields by its
# RTL name, for example "AlphaBits=12;AccGuardBits=0" (VolumePro's
# compositor). Empty: the defaults (rtl/cube4_pkg.sv). Every system variant
# gets the overrides its top module declares; a frame whose scene asks for
# other widths is refused before it starts, naming the width.
#
# The names and ranges are read from kPrecisionFields itself, so that the
# table stays the one list of widths; a name or value it does not allow
# stops the configure step.
set(CUBE4_SYSTEM_WIDTHS "" CACHE STRING
  "widths of the system model's RTL: Verilog parameter overrides such as AlphaBits=12;AccGuardBits=0 (empty: the defaults)")

file(STRINGS ${PROJECT_SOURCE_DIR}/golden/precision.hpp _fields
  REGEX "^ *\\{\"[a-z_]+\", &Precision::[a-z_]+, [0-9]+, [0-9]+, \"P_[A-Z_]+\", \"[A-Za-z]+\"\\},")
set(_known "")
foreach(line ${_fields})
  string(REGEX MATCH "\\{\"([a-z_]+)\", &Precision::[a-z_]+, ([0-9]+), ([0-9]+), \"P_[A-Z_]+\", \"([A-Za-z]+)\"" _ "${line}")
  set(_key_${CMAKE_MATCH_4} ${CMAKE_MATCH_1})
  set(_lo_${CMAKE_MATCH_4} ${CMAKE_MATCH_2})
  set(_hi_${CMAKE_MATCH_4} ${CMAKE_MATCH_3})
  list(APPEND _known ${CMAKE_MATCH_4})
endforeach()
if(NOT _known)
  message(FATAL_ERROR "cmake/system_widths.cmake: found no widths in golden/precision.hpp's kPrecisionFields")
endif()
# Voxel tags have variants of their own (CUBE4_SYSTEM_TAG_PIPES).
list(REMOVE_ITEM _known VoxelTagBits)

# cube4_pkg_default(<out> <Name>): rtl/cube4_pkg.sv's value of a width.
function(cube4_pkg_default out name)
  file(STRINGS ${PROJECT_SOURCE_DIR}/rtl/cube4_pkg.sv _line REGEX "localparam int unsigned +${name} ")
  if(NOT _line MATCHES "= *([0-9]+)")
    message(FATAL_ERROR "cmake/system_widths.cmake: rtl/cube4_pkg.sv has no default for ${name}")
  endif()
  set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

# cube4_system_width(<out> <Name>): the system's value of a width, the
# override or the default.
function(cube4_system_width out name)
  foreach(w ${CUBE4_SYSTEM_WIDTHS})
    if(w MATCHES "^${name}=([0-9]+)$")
      set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  cube4_pkg_default(_value ${name})
  set(${out} ${_value} PARENT_SCOPE)
endfunction()

set(_seen "")
foreach(w ${CUBE4_SYSTEM_WIDTHS})
  if(NOT w MATCHES "^([A-Za-z]+)=([0-9]+)$")
    message(FATAL_ERROR "CUBE4_SYSTEM_WIDTHS: \"${w}\" is not Name=value (for example AlphaBits=12)")
  endif()
  set(_name ${CMAKE_MATCH_1})
  set(_value ${CMAKE_MATCH_2})
  if(_name STREQUAL "VoxelTagBits")
    message(FATAL_ERROR "CUBE4_SYSTEM_WIDTHS: VoxelTagBits is not a system width: voxel tags have RTL variants of "
                        "their own (CUBE4_SYSTEM_TAG_PIPES)")
  endif()
  if(NOT _name IN_LIST _known)
    string(REPLACE ";" ", " _list "${_known}")
    message(FATAL_ERROR "CUBE4_SYSTEM_WIDTHS: ${_name} is not a width of the RTL (one of ${_list})")
  endif()
  if(_name IN_LIST _seen)
    message(FATAL_ERROR "CUBE4_SYSTEM_WIDTHS: ${_name} is given twice")
  endif()
  list(APPEND _seen ${_name})
  if(_value LESS _lo_${_name} OR _value GREATER _hi_${_name})
    message(FATAL_ERROR "CUBE4_SYSTEM_WIDTHS: ${_name}=${_value} is outside precision.${_key_${_name}}'s range "
                        "${_lo_${_name}} to ${_hi_${_name}} (golden/precision.hpp)")
  endif()
endforeach()

# The gradient ring's stream tag width (cube4_gradient_ring's, which the
# interpolation ring carries as its TagBits) at the rings' WeightBits
# (cube4_pkg's default unless given) and SupersamplingBits 4: the layout of
# systemc/rtl/gradient_tag.hpp, whose gradient_tag_bits the C++ checks
# against the value this gives.
function(cube4_gradient_tag_bits out user_tag_bits)
  if(ARGC GREATER 2)
    set(_weight_bits ${ARGV2})
  else()
    cube4_pkg_default(_weight_bits WeightBits)
  endif()
  math(EXPR _bits "4 * (${_weight_bits} + 1) + 4 + 2 + ${user_tag_bits}")
  set(${out} ${_bits} PARENT_SCOPE)
endfunction()

# The interpolation ring carries the gradient ring's stream tag, with
# FramePlan's 16 user bits, in a 64-bit word of the C++ stream.
cube4_system_width(_weight_bits WeightBits)
cube4_gradient_tag_bits(_tag_bits 16 ${_weight_bits})
if(_tag_bits GREATER 64)
  message(FATAL_ERROR "CUBE4_SYSTEM_WIDTHS: WeightBits=${_weight_bits} makes the rings' stream tag ${_tag_bits} bits, "
                      "more than the 64 the system's stream carries (WeightBits at most 9 at RTL)")
endif()

# A voxel word {tag, value} is at most 16 bits (the voxel memory's): wider
# voxels leave no room for bela's four-bit tags, and the tag variants are
# left out.
cube4_system_width(_voxel_bits VoxelBits)
if(_voxel_bits GREATER 12 AND CUBE4_SYSTEM_TAG_PIPES)
  message(WARNING "CUBE4_SYSTEM_WIDTHS: VoxelBits=${_voxel_bits} leaves no room for four-bit voxel tags in a "
                  "16-bit voxel word; no RTL variant with voxel tags is built (CUBE4_SYSTEM_TAG_PIPES ignored)")
  set(CUBE4_SYSTEM_TAG_PIPES "")
endif()
unset(_seen)
unset(_fields)
