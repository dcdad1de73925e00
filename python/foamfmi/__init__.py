"""Helpers shared by the project's Python scripts: the tutorials' analyses,
the benchmarks and the tests.

  dictionary      OpenFOAM dictionary entries: read a scalar, word or
                  vector, the boundary file, set an entry
  postprocessing  tables of postProcessing/ and of the connectors' outputs,
                  probes (wave gauges) and the free-surface elevation
  waves           linear dispersion relation, group velocity, Stokes II,
                  the inlet's waves of constant/waveProperties
  harmonics       least-squares harmonic fits (numpy), up-crossing period,
                  incident and reflected waves from two gauges
  catenary        elastic catenary with seabed contact (a mooring line)
  foamdict        OpenFOAM dictionaries parsed into nested dictionaries
                  (#include, $macros): a restraint's entries
  scene           what tutorials/bin/renderScene draws, read from a case
  scenedraw       its drawing through ParaView's VTK (pvbatch): water,
                  tank, bodies, lines, connectors, labels
  sceneview       its camera and picture
  connectorscene  its springs, dampers and hinges: kinds, attachment
                  points placed by the bodies' motion, their shapes
  bodystate       the bodies' place from the state written at a time
                  (rigidBodyMotion's joints' q, sixDoF's centre and
                  orientation)
  floatingobject  OpenFOAM's floatingObject tutorial as a light-body case
  plots           figures through gnuplot: terminal, window, a body's response
  cli             the scripts' command lines (argparse), error exits and
                  scratch folders
  bridgecase      throw-away rigid-body cases with no fluid, run by
                  rigidBodySim (the bridge's tests and benchmarks), and
                  their rigidBodyMotion dictionaries
  implicitcase    the same loading implicitNewmark's library; the
                  single-body spring model
  sixdofcase      sixDoFRigidBodyMotion cases with no fluid, run by
                  sixDoFSim
  mooringcase     the mooring line of the bridge's moored-body cases

etc/bashrc puts the folder above this package on PYTHONPATH. Only
harmonics needs numpy (Debian's python3-numpy, /usr/bin/python3).
"""
