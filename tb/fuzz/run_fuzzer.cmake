# ctest driver of one fuzzer: fresh seeds, then FUZZER for SECONDS on a
# scratch corpus. libFuzzer exits non-zero on a crash, a sanitizer finding,
# a leak, a timeout (-timeout) or an input over the RSS limit; the input is
# kept beside the corpus (crash-*, timeout-*, oom-*) for the report.
file(REMOVE_RECURSE ${SEEDS} ${SEEDS}.work)
file(MAKE_DIRECTORY ${SEEDS} ${SEEDS}.work)
set(ENV{CUBE4_FUZZ_SEEDS} ${SEEDS})
set(ENV{CUBE4_SOURCE} ${SOURCE})
execute_process(COMMAND ${FUZZER} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER}: writing the seed corpus failed (${rc})")
endif()
unset(ENV{CUBE4_FUZZ_SEEDS})
execute_process(COMMAND ${FUZZER} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048
                        -print_final_stats=1 -artifact_prefix=${SEEDS}.work/ ${SEEDS}.work ${SEEDS}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER}: finding (exit ${rc}); the input is in ${SEEDS}.work/")
endif()
