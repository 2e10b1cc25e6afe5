# The command line's sources but main.cpp, as absolute paths: the gmcc executable's, and what the
# fuzz targets that run a whole command in-process (fuzz/CMakeLists.txt) compile with their flags.
set(GMCC_CLI_SOURCES)
foreach(source select select_batch batch_scene_plain select_record_json select_3d json_output integer_option expansion_option output_files accuracy reproduce merge
               exit_cleanup limit_exit time_limit memory_limit provenance estimate pixel_options canonical benchmark benchmark_merge dataset)
  list(APPEND GMCC_CLI_SOURCES ${CMAKE_CURRENT_LIST_DIR}/${source}.cpp)
endforeach()
