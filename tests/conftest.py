"""pytest options of the jkrcyl suite."""


def pytest_addoption(parser):
    parser.addoption("--update-generated", action="store_true", default=False,
                     help="tests/test_generated_up_to_date.py: write the fresh derivation into generated/ "
                          "instead of failing on a difference (compare-or-update, like make derive)")
