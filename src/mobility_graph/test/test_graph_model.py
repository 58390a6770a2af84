import unittest

from mobility_graph.graph_model import (MODE_ALL, MODE_NODES, NODE, TOPIC, Options,
                                        SystemState, build_graph)

# getSystemState's shape: [[topic, [nodes]] publishers, ... subscribers, ... services]
MASTER_STATE = [
    [['/chatter', ['/talker']], ['/rosout', ['/talker', '/listener', '/graph_view_1']],
     ['/rosout_agg', ['/rosout']], ['/odom', ['/sim']], ['/scan', ['/sim']]],
    [['/chatter', ['/listener', '/sim']], ['/rosout', ['/rosout']], ['/cmd_vel', ['/sim']],
     ['/scan', ['/listener']]],
    [],
]


def edges(graph):
    return sorted((e.source.id, e.target.id, e.label) for e in graph.edges)


def build(**options):
    return build_graph(SystemState.from_master(MASTER_STATE), Options(**options))


class AllModeTest(unittest.TestCase):
    def test_publishers_point_to_topics_and_topics_to_subscribers(self):
        graph = build(mode=MODE_ALL)
        self.assertEqual(graph.names(NODE), ['/listener', '/sim', '/talker'])
        self.assertEqual(graph.names(TOPIC), ['/chatter', '/cmd_vel', '/odom', '/scan'])
        self.assertEqual(edges(graph), sorted([
            ('n:/talker', 't:/chatter', ''), ('t:/chatter', 'n:/listener', ''),
            ('t:/chatter', 'n:/sim', ''), ('t:/cmd_vel', 'n:/sim', ''),
            ('n:/sim', 't:/odom', ''), ('n:/sim', 't:/scan', ''),
            ('t:/scan', 'n:/listener', '')]))

    def test_debug_shown_on_request(self):
        graph = build(mode=MODE_ALL, hide_debug=False)
        self.assertIn('/rosout', graph.names(NODE))
        self.assertIn('/graph_view_1', graph.names(NODE))
        self.assertEqual(set(graph.names(TOPIC)) - set(build(mode=MODE_ALL).names(TOPIC)),
                         {'/rosout', '/rosout_agg'})
        self.assertIn(('n:/rosout', 't:/rosout_agg', ''), edges(graph))

    def test_filter_on_a_node_shows_its_topics(self):
        graph = build(mode=MODE_ALL, filter_text='talker')
        self.assertEqual(graph.names(NODE), ['/talker'])
        self.assertEqual(edges(graph), [('n:/talker', 't:/chatter', '')])

    def test_filter_on_a_topic_shows_its_nodes(self):
        graph = build(mode=MODE_ALL, filter_text='^/scan$')
        self.assertEqual(graph.names(NODE), ['/listener', '/sim'])
        self.assertEqual(graph.names(TOPIC), ['/scan'])

    def test_exclusion_removes_a_node_and_its_edges(self):
        graph = build(mode=MODE_ALL, filter_text='-listener')
        self.assertNotIn('/listener', graph.names(NODE))
        self.assertFalse([e for e in edges(graph) if 'listener' in e[0] + e[1]])


class NodesModeTest(unittest.TestCase):
    def test_edges_join_publisher_and_subscriber_labelled_by_topic(self):
        graph = build(mode=MODE_NODES)
        self.assertEqual(graph.names(TOPIC), [])
        self.assertEqual(graph.names(NODE), ['/listener', '/sim', '/talker'])
        self.assertEqual(edges(graph), [('n:/sim', 'n:/listener', '/scan'),
                                        ('n:/talker', 'n:/listener', '/chatter'),
                                        ('n:/talker', 'n:/sim', '/chatter')])

    def test_filter_keeps_the_peers_of_a_selected_node(self):
        graph = build(mode=MODE_NODES, filter_text='talker')
        self.assertEqual(graph.names(NODE), ['/listener', '/sim', '/talker'])
        self.assertEqual(len(graph.edges), 2)

    def test_several_topics_between_two_nodes_make_one_edge(self):
        state = SystemState({'/a': ('/p',), '/b': ('/p',)}, {'/a': ('/s',), '/b': ('/s',)})
        graph = build_graph(state, Options(mode=MODE_NODES))
        self.assertEqual(edges(graph), [('n:/p', 'n:/s', '/a\n/b')])


class OptionsTest(unittest.TestCase):
    def test_unknown_mode_is_named(self):
        with self.assertRaisesRegex(ValueError, "'topics'"):
            Options(mode='topics')

    def test_bad_regex_is_named(self):
        with self.assertRaisesRegex(ValueError, r"bad filter expression '\('"):
            build(filter_text='(')
