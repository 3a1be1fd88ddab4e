"""PYC089: cv_bridge decodes an image message with the method of the other image kind."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._message_instances import known_messages
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees

_RAW, _COMPRESSED = "sensor_msgs/msg/Image", "sensor_msgs/msg/CompressedImage"
_DECODES = {"imgmsg_to_cv2": _RAW, "compressed_imgmsg_to_cv2": _COMPRESSED}
"""cv_bridge's methods turning a message into an OpenCV image, by the message they take."""
_WHAT_FAILS = {
    _RAW: "cv2.imdecode() finds no compressed picture in raw pixels and returns None, which "
          "the next use of the frame fails on",
    _COMPRESSED: "a `CompressedImage` has no `encoding` field: AttributeError"}


@rule("PYC089", "image-decoded-as-other-kind", Severity.ERROR,
      fix="Use `imgmsg_to_cv2` for a `sensor_msgs/msg/Image` and `compressed_imgmsg_to_cv2` "
          "for a `sensor_msgs/msg/CompressedImage`")
def image_decoded_as_other_kind(package: Package) -> Iterator[Hit]:
    """cv_bridge's decoder for compressed images is given a raw image, or the other way round.

    ## What it does
    Reports `bridge.compressed_imgmsg_to_cv2(msg)` where `msg` is certainly a
    `sensor_msgs/msg/Image` (a subscription callback's message, a fresh or annotated message:
    the instances PYC019 knows), and `bridge.imgmsg_to_cv2(msg)` where it is a
    `sensor_msgs/msg/CompressedImage` (not in a module defining a function of that name: a
    helper of its own).

    ## Why is this bad?
    `compressed_imgmsg_to_cv2` runs `cv2.imdecode()` on the message's bytes: raw pixels are
    no JPEG or PNG, so it returns None and the frame's first use fails (`NoneType` has no
    `shape`), on every message. `imgmsg_to_cv2` reads `encoding`, which a `CompressedImage`
    does not have. Subscriptions to `image_raw` and to `image_raw/compressed` are easily
    swapped when a node is copied.

    ## Example
    ```python
    self.create_subscription(Image, 'camera/image_raw', self.on_image, 10)

    def on_image(self, msg):
        frame = self.bridge.compressed_imgmsg_to_cv2(msg)
    ```

    ## Use instead
    ```python
    def on_image(self, msg):
        frame = self.bridge.imgmsg_to_cv2(msg, 'bgr8')
    ```
    """
    for module, tree, index in installed_trees(package):
        if "imgmsg_to_cv2" not in package.texts.get(module.path, ""):
            continue
        for instance in message_instances(package, tree, index,
                                          known_messages(package, index)):
            kind = instance.message.name
            if kind not in _WHAT_FAILS:
                continue
            for ref in instance.refs:
                call = index.parents.get(id(ref))
                if isinstance(call, ast.Call) and call.args and call.args[0] is ref and \
                        isinstance(call.func, ast.Attribute) and \
                        _DECODES.get(call.func.attr, kind) != kind and \
                        not index.defines_function(call.func.attr):  # a helper of its own
                    yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                              f"`{shortened(ast.unparse(call))}` decodes a "
                              f"`{_DECODES[call.func.attr]}`, but `{ast.unparse(ref)}` is a "
                              f"`{kind}`: {_WHAT_FAILS[kind]}")
