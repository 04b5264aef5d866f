# The glTF files the tests export, validated (tests/gltf/CMakeLists.txt says how):
#
#   cmake -DNODE=<node or NODE-NOTFOUND> -DWEB_DIR=<web/> -DKEEP_DIR=<folder>
#         -DUNIT_TESTS=<shadowgen_unit_tests> -DCLI_TESTS=<cli_tests> -DSHADOWGEN=<shadowgen>
#         -DEXPORT_MODELS=<examples/export_models.sh> -P validate_exports.cmake

if(NOT NODE)
  message("gltf.validator skipped: node (Node.js) is not installed, so the Khronos glTF "
          "validator cannot run; .ci/install-deps installs it")
  return()
endif()
if(NOT EXISTS ${WEB_DIR}/node_modules/gltf-validator/package.json)
  message(FATAL_ERROR "the Khronos glTF validator is not installed in ${WEB_DIR}/node_modules: "
                      "run web/install.sh")
endif()

file(REMOVE_RECURSE ${KEEP_DIR})
file(MAKE_DIRECTORY ${KEEP_DIR})
foreach(run "${UNIT_TESTS};--gtest_filter=GltfExport.*:ViewerModel.*"
            "${CLI_TESTS};--gtest_filter=ExportCli.Gltf*:ExportCli.MinusONames*:SunHoursCli.Gltf*"
            "bash;${EXPORT_MODELS};${SHADOWGEN};--out;${KEEP_DIR}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env SHADOWGEN_GLTF_KEEP=${KEEP_DIR} ${run}
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${run} failed (${result}):\n${output}")
  endif()
endforeach()

execute_process(COMMAND ${NODE} ${WEB_DIR}/validate_gltf.mjs ${KEEP_DIR}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the glTF validator found errors in the exported files (above)")
endif()
