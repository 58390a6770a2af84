// Boost's bind placeholders (_1, _2, ...) in the global namespace, as Noetic-era code
// expects: it writes boost::bind(&C::f, this, _1) and relied on ROS headers that
// included <boost/bind.hpp>. Debian 12's ROS headers include <boost/bind/bind.hpp>,
// which keeps them in boost::placeholders, so that code fails with
// "'_1' was not declared in this scope". The overlay toolchain force-includes this
// header (-include) into every C++ file of an overlay package.
#pragma once
#ifndef BOOST_BIND_GLOBAL_PLACEHOLDERS
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#endif
#include <boost/bind.hpp>
