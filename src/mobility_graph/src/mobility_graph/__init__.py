"""Node graph of a running ROS system: model, Graphviz output, window and command line."""
