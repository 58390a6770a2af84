"""Reads the vertices and edges back out of an SVG written by Graphviz (test helper)."""
import xml.etree.ElementTree as ET

SVG = '{http://www.w3.org/2000/svg}'


def read_svg_graph(path):
    """(vertex ids, edges as (source id, target id)) named in the SVG's <title>s."""
    vertices, edges = set(), set()
    for group in ET.parse(path).getroot().iter(SVG + 'g'):
        title = group.find(SVG + 'title')
        if title is None:
            continue
        if group.get('class') == 'node':
            vertices.add(title.text)
        elif group.get('class') == 'edge':
            edges.add(tuple(title.text.split('->')))
    return vertices, edges


def read_svg_labels(path):
    """Every text drawn in the SVG (vertex and edge labels)."""
    return {t.text for t in ET.parse(path).getroot().iter(SVG + 'text')}
