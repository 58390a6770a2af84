"""Waiting until the master knows a set of publications and subscriptions (test helper)."""
import rosgraph

from mobility_testing.waiting import wait_for


def wait_for_connections(publications, subscriptions, timeout_s=30.0):
    """publications / subscriptions: iterables of (node, topic) the master must list."""
    master = rosgraph.Master('/graph_test_wait')

    def registered():
        pubs, subs, _ = master.getSystemState()
        have_pub = {(n, t) for t, nodes in pubs for n in nodes}
        have_sub = {(n, t) for t, nodes in subs for n in nodes}
        return set(publications) <= have_pub and set(subscriptions) <= have_sub
    wait_for(registered, timeout_s, f'publications {publications} and subscriptions '
                                    f'{subscriptions} at the master')
