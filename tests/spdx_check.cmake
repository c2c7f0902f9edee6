# SPDX-License-Identifier: Apache-2.0
# Every source, build and script file carries the project's SPDX licence line (label unit).
file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR}
  ${SOURCE_DIR}/src/*.cpp ${SOURCE_DIR}/src/*.hpp ${SOURCE_DIR}/src/*.in
  ${SOURCE_DIR}/apps/*.cpp ${SOURCE_DIR}/apps/*.hpp
  ${SOURCE_DIR}/tests/*.cpp ${SOURCE_DIR}/tests/*.hpp ${SOURCE_DIR}/tests/*.py ${SOURCE_DIR}/tests/*.cmake
  ${SOURCE_DIR}/tests/*CMakeLists.txt ${SOURCE_DIR}/bench/*.cpp ${SOURCE_DIR}/bench/CMakeLists.txt
  ${SOURCE_DIR}/python/*.py ${SOURCE_DIR}/python/*.cpp ${SOURCE_DIR}/scripts/*
  ${SOURCE_DIR}/examples/*.py ${SOURCE_DIR}/cmake/*)
list(APPEND files CMakeLists.txt .ci/run)
set(missing "")
foreach(f ${files})
  file(READ ${SOURCE_DIR}/${f} head LIMIT 300)
  if(NOT head MATCHES "SPDX-License-Identifier: Apache-2.0")
    list(APPEND missing ${f})
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "files without an SPDX-License-Identifier line: ${missing}")
endif()
list(LENGTH files n)
message("${n} files carry the licence line")
