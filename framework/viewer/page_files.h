#pragma once
// The page's files (framework/viewer/page/), built into the viewer's program (page_files.cmake
// writes them into page_files.cpp), so that the page needs nothing from disk or the network.
#include <string_view>

// The file's contents, or nullptr if the page has no such file.
const std::string_view* page_file(std::string_view name);
