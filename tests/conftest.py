"""pytest options of the jkrcyl suite."""


def pytest_addoption(parser):
    parser.addoption("--update-generated", action="store_true", default=False,
                     help="tests/test_generated_up_to_date.py: write the fresh derivation into generated/ "
                          "instead of failing on a difference (compare-or-update, like make derive)")


def pytest_configure(config):
    """CI (the CI variable set, as .ci/run does): hypothesis draws a fixed sequence of examples (derandomize), so
    a green run on a developer's machine with CI=true is the run CI makes; locally the draws vary (more ground
    covered over time, failures saved in .hypothesis/)."""
    import os

    from hypothesis import settings
    settings.register_profile("ci", derandomize=True, database=None)
    if os.environ.get("CI"):
        settings.load_profile("ci")
