#!/usr/bin/env python3
"""Compare two XML files the way the xacro tests define "the same XML".

Two documents are the same when, at every level (the document itself and
each element):

- the children come in the same order: elements, comments, processing
  instructions and non-blank text;
- elements have the same (qualified) name and the same attributes with the
  same values; attribute order does not matter;
- text is compared with its surrounding whitespace stripped, whitespace
  inside it kept; text that is only whitespace is ignored; adjacent text
  pieces (character data split by the parser, CDATA) count as one;
- comments are compared exactly, whitespace included;
- numbers are plain text: "1.0" and "1" differ.

Namespace declarations (xmlns, xmlns:*) are ordinary attributes here and are
compared like any other. xacro does move declarations (it removes
xmlns:xacro, and copies the xmlns:* of an included file's root onto the
element that held the <xacro:include>), but it does so deterministically, so
a native expander must produce them at the same places. --ignore-xmlns
leaves them out of the comparison, for debugging.

The XML declaration and the DOCTYPE are not compared.

Usage: xml_compare.py EXPECTED ACTUAL [--ignore-xmlns] [--drop-line2-comment]
Exit status: 0 same, 1 different (the first difference is printed),
2 a file cannot be read or parsed.
"""

import argparse
import sys
import xml.parsers.expat


class Node:
    __slots__ = ('kind', 'name', 'attrs', 'text', 'children', 'line')

    def __init__(self, kind, name='', attrs=None, text='', line=0):
        self.kind = kind          # 'doc', 'elem', 'text', 'comment', 'pi'
        self.name = name
        self.attrs = attrs or {}
        self.text = text
        self.children = []
        self.line = line


class XmlError(Exception):
    pass


def parse_bytes(data, label='<input>'):
    """Parses XML bytes into a Node tree (the 'doc' node)."""
    parser = xml.parsers.expat.ParserCreate()  # no namespace processing
    parser.buffer_text = True
    parser.ordered_attributes = False
    root = Node('doc')
    stack = [root]
    pending = []  # text pieces of the current run

    def flush():
        if pending:
            text = ''.join(pending)
            pending.clear()
            stack[-1].children.append(Node('text', text=text, line=parser.CurrentLineNumber))

    def start(name, attrs):
        flush()
        node = Node('elem', name=name, attrs=dict(attrs), line=parser.CurrentLineNumber)
        stack[-1].children.append(node)
        stack.append(node)

    def end(name):
        flush()
        stack.pop()

    def chars(data):
        pending.append(data)

    def comment(data):
        flush()
        stack[-1].children.append(Node('comment', text=data, line=parser.CurrentLineNumber))

    def pi(target, data):
        flush()
        stack[-1].children.append(Node('pi', name=target, text=data, line=parser.CurrentLineNumber))

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = chars
    parser.CommentHandler = comment
    parser.ProcessingInstructionHandler = pi
    try:
        parser.Parse(data, True)
    except xml.parsers.expat.ExpatError as e:
        raise XmlError('%s: XML error: %s' % (label, e))
    flush()
    return root


def parse_file(path):
    try:
        with open(path, 'rb') as f:
            data = f.read()
    except OSError as e:
        raise XmlError('%s: cannot read: %s' % (path, e.strerror))
    return parse_bytes(data, path)


def drop_line2_comment(data):
    """Removes line 2 of a corpus reference expansion (a comment the corpus
    added: xacro commit and args). Checks that it is one whole comment."""
    lines = data.split(b'\n')
    if len(lines) < 2 or not (lines[1].startswith(b'<!--') and lines[1].rstrip().endswith(b'-->')):
        raise XmlError('line 2 is not a one-line comment')
    del lines[1]
    return b'\n'.join(lines)


def _items(node):
    """The children that count: non-blank text stripped, the rest as is."""
    out = []
    for c in node.children:
        if c.kind == 'text':
            t = c.text.strip()
            if t:
                out.append(Node('text', text=t, line=c.line))
        else:
            out.append(c)
    return out


def _step(item, counters):
    if item.kind == 'elem':
        key, label = item.name, item.name
    elif item.kind == 'text':
        key, label = 'text()', 'text()'
    elif item.kind == 'comment':
        key, label = 'comment()', 'comment()'
    else:
        key, label = 'pi()', 'processing-instruction(%s)' % item.name
    counters[key] = counters.get(key, 0) + 1
    return '%s[%d]' % (label, counters[key])


def _describe(item):
    if item is None:
        return '(nothing)'
    if item.kind == 'elem':
        return '<%s> (line %d)' % (item.name, item.line)
    if item.kind == 'text':
        return 'text %r (line %d)' % (item.text, item.line)
    if item.kind == 'comment':
        return 'comment %r (line %d)' % (item.text, item.line)
    return 'processing instruction <?%s %s?>' % (item.name, item.text)


def _attrs(node, ignore_xmlns):
    if not ignore_xmlns:
        return node.attrs
    return {k: v for k, v in node.attrs.items() if k != 'xmlns' and not k.startswith('xmlns:')}


def compare_nodes(a, b, path='', ignore_xmlns=False):
    """Returns None when a and b are the same, else (path, expected, actual)."""
    if a.kind == 'elem':
        aa, ba = _attrs(a, ignore_xmlns), _attrs(b, ignore_xmlns)
        for name in sorted(set(aa) | set(ba)):
            va, vb = aa.get(name), ba.get(name)
            if va != vb:
                return ('%s/@%s' % (path, name),
                        '(absent)' if va is None else repr(va),
                        '(absent)' if vb is None else repr(vb))
    ia, ib = _items(a), _items(b)
    counters_a, counters_b = {}, {}
    for i in range(max(len(ia), len(ib))):
        ca = ia[i] if i < len(ia) else None
        cb = ib[i] if i < len(ib) else None
        sa = _step(ca, counters_a) if ca is not None else None
        sb = _step(cb, counters_b) if cb is not None else None
        if ca is None or cb is None or ca.kind != cb.kind or sa != sb:
            step = sa if sa is not None else sb
            return ('%s/%s' % (path, step), _describe(ca), _describe(cb))
        if a.kind == 'doc' and ca.kind == 'elem':
            sa = ca.name  # the root element: /robot, not /robot[1]
        here = '%s/%s' % (path, sa)
        if ca.kind in ('text', 'comment', 'pi'):
            if ca.text != cb.text:
                return (here, _describe(ca), _describe(cb))
        else:
            diff = compare_nodes(ca, cb, here, ignore_xmlns)
            if diff:
                return diff
    return None


def compare_files(expected, actual, ignore_xmlns=False, expected_filter=None):
    """Compares two files. expected_filter(bytes) -> bytes may rewrite the
    expected file first. Returns None or (path, expected, actual); raises
    XmlError when a file cannot be read or parsed."""
    try:
        with open(expected, 'rb') as f:
            data = f.read()
    except OSError as e:
        raise XmlError('%s: cannot read: %s' % (expected, e.strerror))
    if expected_filter:
        try:
            data = expected_filter(data)
        except XmlError as e:
            raise XmlError('%s: %s' % (expected, e))
    return compare_nodes(parse_bytes(data, expected), parse_file(actual), '', ignore_xmlns)


def format_diff(diff):
    path, va, vb = diff
    return '%s\n  expected: %s\n  actual:   %s' % (path, va, vb)


def main(argv=None):
    ap = argparse.ArgumentParser(description='Compare two XML files (see the module docstring).')
    ap.add_argument('expected')
    ap.add_argument('actual')
    ap.add_argument('--ignore-xmlns', action='store_true',
                    help='leave xmlns and xmlns:* attributes out of the comparison')
    ap.add_argument('--drop-line2-comment', action='store_true',
                    help="drop line 2 of EXPECTED (the comment a corpus reference expansion adds)")
    args = ap.parse_args(argv)
    try:
        diff = compare_files(args.expected, args.actual, args.ignore_xmlns,
                             drop_line2_comment if args.drop_line2_comment else None)
    except XmlError as e:
        print('xml_compare: %s' % e, file=sys.stderr)
        return 2
    if diff:
        print('different at ' + format_diff(diff))
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
