"""Listing the sensor_msgs/Image topics that the ROS master knows publishers for."""
IMAGE_TYPE = 'sensor_msgs/Image'


class MasterUnavailable(RuntimeError):
    """The ROS master did not answer."""


def image_topics(published):
    """Sorted names of the image topics in a list of (name, type) pairs."""
    return sorted({name for name, msg_type in published if msg_type == IMAGE_TYPE})


def choices(topics, selected):
    """The drop-down entries: the image topics plus the selected one if it is missing
    (a topic given on the command line may be published later)."""
    if selected and selected not in topics:
        return sorted(list(topics) + [selected])
    return list(topics)


def query_image_topics(master):
    """Image topics from a rosgraph.Master-like object (getPublishedTopics)."""
    try:
        published = master.getPublishedTopics('')
    except Exception as error:  # the XML-RPC layer raises socket and protocol errors
        raise MasterUnavailable(f'cannot list topics from the ROS master: {error}') from error
    return image_topics(published)
