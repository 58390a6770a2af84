// Noetic's name of <pluginlib/class_loader.hpp>, which Debian 12 ships under the new name only.
#pragma once
#include <pluginlib/class_loader.hpp>
