"""One module per identification method: its keyword wrappers over the bindings of
python/src/methods/NAME.cpp. frictionlab.identify imports the module of every method the
library's table lists (frictionlab/identify/method.hpp) and the package exports each module's
__all__: adding a method's Python side is its two files (python/src/methods/NAME.cpp and this
folder's NAME.py) and one line in python/src/methods/methods.cpp."""
