# cmake -DBUILD=DIR -DPREFIX=DIR -DCONFIG=NAME -P install.cmake: installs the
# build tree BUILD into PREFIX emptied first, so that a header no longer
# installed does not linger there for the consumer to find.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --config "${CONFIG}" --prefix "${PREFIX}"
  COMMAND_ERROR_IS_FATAL ANY)
