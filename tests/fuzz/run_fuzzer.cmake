# SPDX-License-Identifier: Apache-2.0
# Runs one libFuzzer target for SECONDS from the SEEDS (read only) into SCRATCH; fails on any crash,
# leak, sanitizer report or timeout of one input (5 s).
file(MAKE_DIRECTORY ${SCRATCH})
execute_process(COMMAND ${FUZZER} ${SCRATCH} ${SEEDS} -max_total_time=${SECONDS} -timeout=5 -rss_limit_mb=2048
                        -max_len=8192 -print_final_stats=1
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fuzz target ${FUZZER} failed (exit ${rc})")
endif()
