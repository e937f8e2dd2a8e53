# SPDX-License-Identifier: MIT
# The racer's sources that make and draw the racing scene on any device: the native demo's
# racer_core (game/CMakeLists.txt) and the web page's racer_web_core (game/web) both build from
# this one list. RACER_SCENE_SOURCES: paths below game/src.
set(RACER_SCENE_SOURCES
  track.cpp
  ground.cpp
  forest.cpp
  racing_scene.cpp
  camera_rig.cpp
  car_driver.cpp
  track_ground.cpp
  content_files.cpp
  plant_levels.cpp
  foliage_upload.cpp
  frame_renderer.cpp
  living_scene.cpp
  verge.cpp
  hud_text.cpp
  compare_layout.cpp
  compare_view.cpp
  window_keys.cpp
)
list(TRANSFORM RACER_SCENE_SOURCES PREPEND ${CMAKE_CURRENT_LIST_DIR}/src/)
