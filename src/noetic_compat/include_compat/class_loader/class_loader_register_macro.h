// Noetic's name of <class_loader/register_macro.hpp>, which Debian 12 ships under the new name only.
#pragma once
#include <class_loader/register_macro.hpp>
