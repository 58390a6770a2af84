// Noetic's name of <class_loader/multi_library_class_loader.hpp>, which Debian 12 ships under the new name only.
#pragma once
#include <class_loader/multi_library_class_loader.hpp>
