// Prints the register tables of docs/registers.md from the register map
// (scripts/update_doc_section.py puts them in place; a test fails when the
// document's copy is stale).
#include <iostream>

#include "systemc/host/register_map.hpp"

int main() { std::cout << cube4::sysc::regmap::register_doc() << "\n"; }
