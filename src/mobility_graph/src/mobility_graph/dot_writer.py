"""The graph as Graphviz DOT text (layout is left to Graphviz's dot)."""
from mobility_graph.graph_model import NODE

FONT = 'DejaVu Sans'
NODE_STYLE = ('shape=ellipse, style=filled, fillcolor="#cfe2f3", color="#3d6a99", '
              f'fontname="{FONT}"')
TOPIC_STYLE = ('shape=box, style="rounded,filled", fillcolor="#fff2cc", color="#b08a2e", '
               f'fontname="{FONT}"')


def quote(text):
    """A DOT string literal."""
    return '"' + text.replace('\\', '\\\\').replace('"', '\\"').replace('\n', '\\n') + '"'


def to_dot(graph, rankdir='LR'):
    lines = ['digraph ros_graph {',
             f'  graph [rankdir={rankdir}, fontname="{FONT}", nodesep=0.3, ranksep=0.6];',
             f'  edge [fontname="{FONT}", fontsize=10, color="#555555"];']
    for vertex in graph.vertices:
        style = NODE_STYLE if vertex.kind == NODE else TOPIC_STYLE
        lines.append(f'  {quote(vertex.id)} [label={quote(vertex.name)}, {style}];')
    for edge in graph.edges:
        label = f' [label={quote(edge.label)}]' if edge.label else ''
        lines.append(f'  {quote(edge.source.id)} -> {quote(edge.target.id)}{label};')
    lines.append('}')
    return '\n'.join(lines) + '\n'
