# Put first on PYTHONPATH by tests/scripts/report.cmake, this package hides Debian's matplotlib, so the test sees
# what a machine without python3-matplotlib sees.
raise ImportError("No module named 'matplotlib' (hidden by tests/report/without_matplotlib)")
