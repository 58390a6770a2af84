"""Reading the system state from the ROS master (the only ROS-facing part of the model)."""
import socket
import xmlrpc.client

import rosgraph

from mobility_graph.graph_model import SystemState


class MasterUnreachable(RuntimeError):
    """The master does not answer; the message names its URI."""


def fetch_state(caller_id='/graph_view'):
    """The master's current publishers and subscribers as a SystemState."""
    master = rosgraph.Master(caller_id)
    try:
        return SystemState.from_master(master.getSystemState())
    except (OSError, socket.error, xmlrpc.client.Error, rosgraph.MasterException) as err:
        raise MasterUnreachable(f'cannot reach the ROS master at {master.master_uri}: '
                                f'{err}') from None
