// A run's outputs, all or nothing (docs/reliability.md). Every output is
// checked and given a unique temporary file in its own folder before any
// work; the writers fill the temporaries; commit() renames them onto their
// destinations only once every one has been written and checked. Otherwise
// (an error, an exception, SIGINT, SIGTERM, SIGHUP) the temporaries are
// removed and no destination is touched.
#pragma once
#include <string>
#include <vector>

namespace cube4::tb {

class OutputSet {
 public:
  OutputSet();
  ~OutputSet();  // removes what was not committed
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Checks `path` (its folder exists, it is not a folder or a device, no
  // other output of the run names the same file) and returns the temporary
  // file to write instead. `what` names the option in messages ("--output").
  // Throws InputError.
  std::string add(const std::string& path, const std::string& what);
  // Traces: a temporary folder beside `path`; the returned name is `path`'s
  // file name inside it, so FILE.UNIT.fst files land there. `suffixes` are
  // the UNIT names that may appear.
  std::string add_trace(const std::string& path, const std::vector<std::string>& suffixes);

  // Throws InputError if `path` (an input of the run, `what`: "the scene")
  // is also one of its outputs: the run would replace what it reads.
  void check_not_output(const std::string& path, const std::string& what) const;

  // Each written file is flushed to disk and must be non-empty; a trace
  // folder must hold at least one trace. Then every temporary is renamed.
  // Throws InputError naming the output that failed (nothing renamed then).
  void commit();
  void discard();

 private:
  struct Entry {
    std::string dest, temp, what;
    bool trace = false;
  };
  void check_destination(const std::string& path, const std::string& what);
  std::vector<Entry> entries_;
  std::vector<std::string> dests_;  // every destination, for the same-file check
};

// FILE.fst + UNIT -> FILE.UNIT.fst, as the RTL models name their traces.
std::string trace_file_for(const std::string& file, const std::string& unit);

}  // namespace cube4::tb
