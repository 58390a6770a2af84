// Noetic's name of <pluginlib/exceptions.hpp>, which Debian 12 ships under the new name only.
#pragma once
#include <pluginlib/exceptions.hpp>
