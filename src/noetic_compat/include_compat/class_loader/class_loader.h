// Noetic's name of <class_loader/class_loader.hpp>, which Debian 12 ships under the new name only.
#pragma once
#include <class_loader/class_loader.hpp>
