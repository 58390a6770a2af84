"""The ROS computation graph as vertices and edges, built from the master's system state.

ROS-free: the input is the (publishers, subscribers) lists that the master's
getSystemState returns, so the rules (modes, debug hiding, filter) are unit-tested."""
import re
from dataclasses import dataclass, field

MODE_NODES = 'nodes'
MODE_ALL = 'all'
MODES = (MODE_NODES, MODE_ALL)

#: Shown only when debug items are not hidden.
DEBUG_NODES = ('/rosout',)
DEBUG_TOPICS = ('/rosout', '/rosout_agg', '/statistics')
#: Name prefixes of the graph tool itself (it may run as a node under either name).
OWN_NODE_PREFIXES = ('/graph_view', '/rqt_graph')

NODE = 'node'
TOPIC = 'topic'


@dataclass(frozen=True)
class SystemState:
    """topic -> publishing nodes and topic -> subscribing nodes."""
    publishers: dict
    subscribers: dict

    @classmethod
    def from_master(cls, state):
        """From getSystemState's [publishers, subscribers, services] lists."""
        publishers, subscribers = state[0], state[1]
        return cls({topic: tuple(nodes) for topic, nodes in publishers},
                   {topic: tuple(nodes) for topic, nodes in subscribers})


@dataclass(frozen=True)
class Options:
    mode: str = MODE_NODES
    hide_debug: bool = True
    filter_text: str = ''

    def __post_init__(self):
        if self.mode not in MODES:
            raise ValueError(f'unknown graph mode {self.mode!r} (expected one of {MODES})')


@dataclass(frozen=True)
class Vertex:
    kind: str
    name: str

    @property
    def id(self):
        return ('n:' if self.kind == NODE else 't:') + self.name


@dataclass(frozen=True)
class Edge:
    source: Vertex
    target: Vertex
    label: str = ''


@dataclass
class Graph:
    vertices: list = field(default_factory=list)
    edges: list = field(default_factory=list)

    def names(self, kind):
        return [v.name for v in self.vertices if v.kind == kind]


class NameFilter:
    """Comma-separated regular expressions searched in names; '-expr' excludes.

    An empty filter (or one with only exclusions) includes everything not excluded."""

    def __init__(self, text):
        self.includes, self.excludes = [], []
        for term in (t.strip() for t in text.split(',')):
            if not term:
                continue
            target = self.excludes if term.startswith('-') else self.includes
            pattern = term[1:] if term.startswith('-') else term
            try:
                target.append(re.compile(pattern))
            except re.error as err:
                raise ValueError(f'bad filter expression {pattern!r}: {err}') from None

    def excluded(self, name):
        return any(p.search(name) for p in self.excludes)

    def selected(self, name):
        """Explicitly matched by an include term (False when there are none)."""
        return any(p.search(name) for p in self.includes) and not self.excluded(name)

    @property
    def selects_all(self):
        return not self.includes


def _hidden_node(name, hide_debug):
    return hide_debug and (name in DEBUG_NODES or name.startswith(OWN_NODE_PREFIXES))


def _connections(state, hide_debug):
    """(node, topic, 'pub'|'sub') triples left after debug hiding."""
    triples = []
    for direction, table in (('pub', state.publishers), ('sub', state.subscribers)):
        for topic, nodes in table.items():
            if hide_debug and topic in DEBUG_TOPICS:
                continue
            triples.extend((node, topic, direction) for node in nodes
                           if not _hidden_node(node, hide_debug))
    return triples


def _not_excluded(triples, name_filter):
    return [(node, topic, direction) for node, topic, direction in triples
            if not (name_filter.excluded(node) or name_filter.excluded(topic))]


def _wanted(name_filter, *names):
    return name_filter.selects_all or any(name_filter.selected(n) for n in names)


def _node_pairs(triples):
    """(publisher node, subscriber node) -> topics that connect them."""
    subscribers = {}
    for node, topic, direction in triples:
        if direction == 'sub':
            subscribers.setdefault(topic, []).append(node)
    pairs = {}
    for node, topic, direction in triples:
        if direction == 'pub':
            for sub_node in subscribers.get(topic, ()):
                pairs.setdefault((node, sub_node), set()).add(topic)
    return pairs


def build_graph(state, options):
    """The graph to draw for a system state under the given options.

    The filter shows what it selects plus the direct neighbours: a selected node with
    its topics (or, nodes only, its peers), a selected topic with its nodes."""
    name_filter = NameFilter(options.filter_text)
    triples = _not_excluded(_connections(state, options.hide_debug), name_filter)
    kept = [t for t in triples if _wanted(name_filter, t[0], t[1])]
    if options.mode == MODE_ALL:
        graph = Graph(vertices=[Vertex(NODE, n) for n in sorted({t[0] for t in kept})]
                      + [Vertex(TOPIC, t) for t in sorted({t[1] for t in kept})])
        for node, topic, direction in sorted(kept):
            pair = (Vertex(NODE, node), Vertex(TOPIC, topic))
            graph.edges.append(Edge(*(pair if direction == 'pub' else pair[::-1])))
        return graph
    pairs = {pair: topics for pair, topics in _node_pairs(triples).items()
             if _wanted(name_filter, *pair, *topics)}
    nodes = {t[0] for t in kept} | {n for pair in pairs for n in pair}
    return Graph(vertices=[Vertex(NODE, n) for n in sorted(nodes)],
                 edges=[Edge(Vertex(NODE, a), Vertex(NODE, b), '\n'.join(sorted(topics)))
                        for (a, b), topics in sorted(pairs.items())])
