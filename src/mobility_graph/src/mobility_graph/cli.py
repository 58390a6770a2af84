"""Command line of graph_view / rqt_graph: the window, or `--output FILE` without one."""
import argparse
import os
import sys

from mobility_graph import graph_model
from mobility_graph.dot_writer import to_dot
from mobility_graph.master_source import MasterUnreachable, fetch_state
from mobility_graph.render import RenderError, output_format, write_graph


def _prog():
    return os.path.basename(sys.argv[0]) or 'graph_view'


def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog=_prog(), description='Draw the ROS node graph (nodes, topics) with Graphviz.')
    parser.add_argument('--output', '-o', metavar='FILE',
                        help='write the graph to FILE (.dot, .svg or .png) and exit, no window')
    parser.add_argument('--mode', choices=graph_model.MODES, default=graph_model.MODE_NODES,
                        help='"nodes": nodes only, edges labelled by topic; "all": nodes and '
                             'topics (default: %(default)s)')
    parser.add_argument('--show-debug', action='store_true',
                        help='also show /rosout, its topics and this tool')
    parser.add_argument('--filter', default='', metavar='REGEXES',
                        help='comma-separated regular expressions; "-regex" excludes')
    parser.add_argument('--auto-refresh', type=float, default=0.0, metavar='SECONDS',
                        help='window only: refresh every SECONDS (default: off)')
    args = parser.parse_args(argv)
    if args.auto_refresh < 0:
        parser.error(f'--auto-refresh must be 0 (off) or positive, got {args.auto_refresh}')
    try:
        args.options = graph_model.Options(args.mode, not args.show_debug, args.filter)
        graph_model.NameFilter(args.filter)
        if args.output:
            output_format(args.output)
    except (ValueError, RenderError) as err:
        parser.error(str(err))
    return args


def write_once(args):
    try:
        graph = graph_model.build_graph(fetch_state(), args.options)
        write_graph(args.output, to_dot(graph))
    except (MasterUnreachable, RenderError) as err:
        print(f'{_prog()}: {err}', file=sys.stderr)
        return 1
    print(f'{_prog()}: wrote {args.output} ({len(graph.vertices)} vertices, '
          f'{len(graph.edges)} edges)')
    return 0


def run_window(args):
    if not (os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY')):
        print(f'{_prog()}: no display (DISPLAY is not set); use --output FILE to write the '
              'graph without a window', file=sys.stderr)
        return 1
    from PyQt5 import QtWidgets

    from mobility_graph.graph_window import GraphWindow
    app = QtWidgets.QApplication(sys.argv[:1])
    window = GraphWindow(fetch_state, args.options, args.auto_refresh)
    window.show()
    return app.exec_()


def main(argv=None):
    import rospy
    argv = rospy.myargv(sys.argv if argv is None else argv)[1:]
    args = parse_args(argv)
    return write_once(args) if args.output else run_window(args)
