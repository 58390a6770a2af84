"""Joint sliders for a robot described in URDF: the model behind the
joint_state_publisher_gui window and node of this workspace."""
