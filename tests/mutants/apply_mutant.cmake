# One mutant's source, outside a build (the fixture test, tests/mutants/test_apply_mutant.cmake, or
# to look at a mutant):
#   cmake -DMUTANT=<name>.mutant -DREFERENCE=<file> -DOUTPUT=<file> -P apply_mutant.cmake
cmake_minimum_required(VERSION 3.24)
include(${CMAKE_CURRENT_LIST_DIR}/mutants.cmake)
foreach(variable MUTANT REFERENCE OUTPUT)
	if(NOT DEFINED ${variable})
		message(FATAL_ERROR "apply_mutant.cmake: -D${variable}=<file> is missing")
	endif()
endforeach()
lab_mutant_source("${MUTANT}" "${REFERENCE}" "${OUTPUT}")
