// Noetic's name of <class_loader/meta_object.hpp>, which Debian 12 ships under the new name only.
#pragma once
#include <class_loader/meta_object.hpp>
