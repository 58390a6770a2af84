import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

from mobility_graph.cli import parse_args
from mobility_graph.dot_writer import quote, to_dot
from mobility_graph.graph_model import MODE_ALL, Options, SystemState, build_graph
from mobility_graph.render import RenderError, output_format, write_graph

SVG = '{http://www.w3.org/2000/svg}'


def sample_dot():
    state = SystemState({'/chatter': ('/talker',)}, {'/chatter': ('/listener',)})
    return to_dot(build_graph(state, Options(mode=MODE_ALL)))


class DotTest(unittest.TestCase):
    def test_quote_escapes(self):
        self.assertEqual(quote('a"b\\c\nd'), '"a\\"b\\\\c\\nd"')

    def test_dot_text_has_vertices_and_directed_edges(self):
        dot = sample_dot()
        self.assertIn('"n:/talker" -> "t:/chatter";', dot)
        self.assertIn('"t:/chatter" -> "n:/listener";', dot)
        self.assertIn('"t:/chatter" [label="/chatter", shape=box', dot)


class WriteTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def test_svg_names_vertices_and_edges(self):
        write_graph(self.path('g.svg'), sample_dot())
        root = ET.parse(self.path('g.svg')).getroot()
        titles = {g.get('class'): [] for g in root.iter(SVG + 'g')}
        for g in root.iter(SVG + 'g'):
            titles[g.get('class')].append(g.find(SVG + 'title').text
                                          if g.find(SVG + 'title') is not None else None)
        self.assertEqual(sorted(titles['node']), ['n:/listener', 'n:/talker', 't:/chatter'])
        self.assertEqual(sorted(titles['edge']), ['n:/talker->t:/chatter',
                                                  't:/chatter->n:/listener'])

    def test_png_and_dot_by_extension(self):
        write_graph(self.path('g.png'), sample_dot())
        with open(self.path('g.png'), 'rb') as png:
            self.assertEqual(png.read(8), b'\x89PNG\r\n\x1a\n')
        write_graph(self.path('g.dot'), sample_dot())
        with open(self.path('g.dot')) as dot:
            self.assertEqual(dot.read(), sample_dot())

    def test_unknown_extension_is_named(self):
        with self.assertRaisesRegex(RenderError, r"'graph.pdf'.*\.dot, \.svg, \.png"):
            output_format('graph.pdf')

    def test_unwritable_path_is_named(self):
        with self.assertRaisesRegex(RenderError, 'cannot write .*/missing/g.dot'):
            write_graph(self.path('missing/g.dot'), sample_dot())


class ArgsTest(unittest.TestCase):
    def test_defaults(self):
        args = parse_args([])
        self.assertEqual(args.options, Options())
        self.assertIsNone(args.output)

    def test_output_mode_and_debug(self):
        args = parse_args(['--output', 'x.svg', '--mode', 'all', '--show-debug'])
        self.assertEqual(args.options, Options(mode='all', hide_debug=False))

    def test_bad_extension_exits_with_usage_error(self):
        with self.assertRaises(SystemExit) as exit_info:
            parse_args(['--output', 'x.jpg'])
        self.assertEqual(exit_info.exception.code, 2)
