# SPDX-License-Identifier: Apache-2.0
# Installs the build tree into a temporary prefix, then configures, builds and runs a consumer
# project that finds it with find_package(blockdyn). Run by ctest (InstallAndFindPackage).
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGV}\n${out}\n${err}")
  endif()
  message("${out}")
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
# Every installed header compiles on its own against the installed tree (none names an
# internal header that was not installed).
file(GLOB_RECURSE headers RELATIVE ${WORK_DIR}/prefix/include ${WORK_DIR}/prefix/include/blockdyn/*.hpp)
list(LENGTH headers n)
if(n LESS 20)
  message(FATAL_ERROR "only ${n} headers installed")
endif()
set(tu "")
foreach(h ${headers})
  string(APPEND tu "#include \"${h}\"\n")
endforeach()
file(WRITE ${WORK_DIR}/all_headers.cpp "${tu}")
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
    -DCMAKE_BUILD_TYPE=Release -DALL_HEADERS=${WORK_DIR}/all_headers.cpp)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
if(NOT EXISTS ${WORK_DIR}/prefix/bin/blockdyn)
  message(FATAL_ERROR "the blockdyn program was not installed")
endif()
run(${WORK_DIR}/prefix/bin/blockdyn --version)
# The Python package, installed under lib/python3/dist-packages, imports and runs, and finds the
# installed plot scripts.
if(EXISTS ${BUILD_DIR}/python/blockdyn/__init__.py)
  file(GLOB site ${WORK_DIR}/prefix/lib*/python3/dist-packages)
  if(NOT site)
    message(FATAL_ERROR "the Python package was not installed")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site}
                  /usr/bin/python3 -c "import blockdyn, os; r = blockdyn.simulate(model='housner', width=0.2, height=1, w0=0.1, t_end=1, plot='${WORK_DIR}/py.png'); print(r, os.environ['BLOCKDYN_PYTHON_DIR'])"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/py.png OR NOT out MATCHES "prefix/share/blockdyn/python")
    message(FATAL_ERROR "installed Python package failed (${rc}):\n${out}\n${err}")
  endif()
  message("${out}")
endif()

