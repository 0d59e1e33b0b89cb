# The renderer's tests (included from tests/CMakeLists.txt): one executable per module.

# the scene's render: block
add_executable(render_yaml_test render_yaml_test.cpp $<TARGET_OBJECTS:test_main>)
target_link_libraries(render_yaml_test PRIVATE rigidreel_scene doctest::doctest)
add_test(NAME render_yaml COMMAND render_yaml_test)
add_executable(render_timing_yaml_test render_timing_yaml_test.cpp $<TARGET_OBJECTS:test_main>)
target_link_libraries(render_timing_yaml_test PRIVATE rigidreel_scene doctest::doctest)
add_test(NAME render_timing_yaml COMMAND render_timing_yaml_test)

# the renderer's modules, one executable each (render/<module>.cpp)
foreach(module image camera png_io text gl_canvas time_map caption)
  add_executable(${module}_test ${module}_test.cpp $<TARGET_OBJECTS:test_main>)
  target_link_libraries(${module}_test PRIVATE rigidreel_render doctest::doctest)
  add_test(NAME ${module} COMMAND ${module}_test)
endforeach()
foreach(module draw_list history frame_painter video recorder survey teaching_arrows energy_panel impact_labels sat_axes)
  add_executable(${module}_test ${module}_test.cpp $<TARGET_OBJECTS:test_main>)
  target_link_libraries(${module}_test PRIVATE rigidreel_render rigidreel_scene doctest::doctest)
  add_test(NAME ${module} COMMAND ${module}_test)
endforeach()

# jobs as child processes (render/job_runner.cpp)
add_executable(job_runner_test job_runner_test.cpp $<TARGET_OBJECTS:test_main>)
target_link_libraries(job_runner_test PRIVATE rigidreel_process doctest::doctest)
add_test(NAME job_runner COMMAND job_runner_test)

# golden images (tests/golden/*.png); `make golden` runs this with RIGIDREEL_UPDATE_GOLDEN=1
add_executable(golden_test golden_test.cpp $<TARGET_OBJECTS:test_main>)
target_link_libraries(golden_test PRIVATE rigidreel_render rigidreel_scene doctest::doctest)
target_compile_definitions(golden_test PRIVATE RIGIDREEL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_test(NAME golden COMMAND golden_test)

# render and snapshot end to end: ffprobe of the video, bad input, ffmpeg failures, Ctrl-C
add_test(NAME render_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/render_cli_test.sh $<TARGET_FILE:rigidreel> ${PROJECT_SOURCE_DIR})

# a golden frame of each lecture scene (scenes/lecture/), against tests/golden/lecture/
add_executable(lecture_golden_test lecture_golden_test.cpp $<TARGET_OBJECTS:test_main>)
target_link_libraries(lecture_golden_test PRIVATE rigidreel_render rigidreel_scene doctest::doctest)
target_compile_definitions(lecture_golden_test PRIVATE RIGIDREEL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_test(NAME lecture_golden COMMAND lecture_golden_test)

# `rigidreel lecture`: a small pack of copies of scenes/ (jobs, summary, --list) and its errors
add_test(NAME lecture_cli COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/lecture_cli_test.sh $<TARGET_FILE:rigidreel> ${PROJECT_SOURCE_DIR})
# the course's pack, scenes/lecture/, at 160x90 and 10 fps: every planned output exists and is valid
add_test(NAME lecture_pack COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/lecture_pack_test.sh $<TARGET_FILE:rigidreel>
  ${PROJECT_SOURCE_DIR}/scenes/lecture ${CMAKE_CURRENT_BINARY_DIR}/lecture_pack)
