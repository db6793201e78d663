"""mdlc.compile's options by keyword, and mdlc.compile_string (issue 59: one
options path, every name checked). A misspelt keyword, warning group, limit
or value is refused with the nearest known name, by the same C++ code that
checks the command line's flags, instead of being ignored.

Run by ctest (python/options) with the built package on PYTHONPATH; every
model is text written here.
"""

import unittest

import mdlc

ONE_BODY = """<robot name="ball">
  <link name="ball">
    <inertial><mass value="1"/>
      <inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
</robot>
"""
# an unknown element: one warning of the group 'unknown'
NOISY = ONE_BODY.replace("<link name=\"ball\">", "<link name=\"ball\"><bogus/>")


class MisspeltNamesAreRefused(unittest.TestCase):
    def assertRefused(self, text, **options):
        with self.assertRaises(ValueError) as caught:
            mdlc.compile_string(ONE_BODY, format="urdf", **options)
        self.assertEqual(str(caught.exception), text)

    def test_an_unknown_keyword_names_the_nearest(self):
        self.assertRefused("unknown keyword 'strcit' for mdlc.compile_string; did you mean "
                           "'strict'?", strcit=True)
        with self.assertRaisesRegex(ValueError, "^unknown keyword 'strcit' for mdlc.compile; "):
            mdlc.compile(ONE_BODY, format="urdf", strcit=True)

    def test_an_unknown_warning_group_names_the_nearest(self):
        self.assertRefused("unknown warning group 'unknwon' in disabled_warnings; did you mean "
                           "'unknown'?", disabled_warnings=["unknwon"])
        self.assertRefused("unknown warning group 'inertai' in error_warnings; did you mean "
                           "'inertia'?", error_warnings=["inertai"])
        self.assertRefused("unknown warning group 'jiont' in warnings (-Wno-jiont); did you "
                           "mean 'joint'?", warnings=["no-jiont"])

    def test_unknown_limits_and_values_name_the_nearest(self):
        self.assertRefused("unknown limit 'dept' in limits; did you mean 'depth'?",
                           limits={"dept": 4})
        self.assertRefused("unknown value 'in-proces' for mesh_reader; did you mean "
                           "'in-process'?", mesh_reader="in-proces")
        self.assertRefused("unknown value 'aply' for collada_up_axis; did you mean 'apply'?",
                           collada_up_axis="aply")

    def test_a_value_of_the_wrong_type_is_a_type_error(self):
        with self.assertRaisesRegex(TypeError, "strict expects a bool, got str"):
            mdlc.compile_string(ONE_BODY, format="urdf", strict="yes")
        with self.assertRaisesRegex(TypeError, "limits expects a dict, got list"):
            mdlc.compile_string(ONE_BODY, format="urdf", limits=["depth=3"])


class KeywordsDoWhatTheirFlagsDo(unittest.TestCase):
    def test_the_keywords_of_earlier_releases_are_still_taken(self):
        for keyword in ("packages", "package_paths", "use_ros_package_path", "strict",
                        "disabled_warnings", "error_warnings", "model_name", "auto_rename",
                        "joint_positions", "limits", "mesh_reader", "xacro_args",
                        "collada_up_axis"):
            self.assertIn(keyword, mdlc.OPTION_NAMES)

    def test_warnings_take_the_text_of_w_flags(self):
        self.assertEqual(len(mdlc.compile_string(NOISY, format="urdf").diagnostics), 1)
        quiet = mdlc.compile_string(NOISY, format="urdf", warnings=["no-unknown"])
        self.assertEqual(list(quiet.diagnostics), [])
        quiet = mdlc.compile_string(NOISY, format="urdf", disabled_warnings="unknown")
        self.assertEqual(list(quiet.diagnostics), [])  # one group, not its letters
        for options in ({"warnings": ["error"]}, {"warnings": ["error=unknown"]},
                        {"error_warnings": ["unknown"]}, {"strict": True}):
            with self.assertRaises(mdlc.CompileError, msg=options):
                mdlc.compile_string(NOISY, format="urdf", **options)

    def test_fixed_base_and_none_for_the_default(self):
        self.assertEqual(mdlc.compile_string(ONE_BODY, format="urdf").num_positions, 7)
        fixed = mdlc.compile_string(ONE_BODY, format="urdf", fixed_base=True, model_name=None)
        self.assertEqual(fixed.num_positions, 0)


class CompileString(unittest.TestCase):
    def test_text_by_format_or_by_name(self):
        self.assertEqual(len(mdlc.compile_string(ONE_BODY, format="urdf").bodies), 2)
        self.assertEqual(len(mdlc.compile_string(ONE_BODY, name="ball.urdf").bodies), 2)
        two = mdlc.compile_string([ONE_BODY, ONE_BODY.replace('"ball"', '"other"', 1)],
                                  format="urdf")
        self.assertEqual(len(two.bodies), 3)

    def test_text_is_never_taken_for_a_path(self):
        # compile("ball.urdf") would look for a file; compile_string reads the text
        with self.assertRaises(mdlc.CompileError):
            mdlc.compile_string("ball.urdf", format="urdf")

    def test_text_needs_a_format_or_a_name(self):
        with self.assertRaisesRegex(ValueError, "^mdlc.compile_string: model text needs "):
            mdlc.compile_string(ONE_BODY)
        with self.assertRaises(TypeError):
            mdlc.compile_string(b"<robot/>", format="urdf")


if __name__ == "__main__":
    unittest.main()
