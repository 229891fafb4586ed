<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" simplifyDrawingTol="1" simplifyAlgorithm="0" simplifyLocal="1" simplifyDrawingHints="1" minScale="100000000" version="3.22.16-Białowieża" hasScaleBasedVisibilityFlag="0" labelsEnabled="1" simplifyMaxScale="1" maxScale="0" symbologyReferenceScale="-1">
  <renderer-v2 symbollevels="0" type="RuleRenderer" enableorderby="1" forceraster="0" referencescale="-1">
    <rules key="{84f8de85-18d9-4393-a96e-9cf86462e3ba}">
      <rule filter="&quot;class_cue&quot; = 'at_mine'" symbol="0" key="{ee0561ab-c57e-4c67-85f8-423c239f0d3c}" label="AT mine indication"/>
      <rule filter="&quot;class_cue&quot; = 'ap_mine'" symbol="1" key="{19510607-75e8-4c8b-8e79-48d48d6f5915}" label="AP mine indication"/>
      <rule filter="&quot;class_cue&quot; NOT IN ('at_mine', 'ap_mine', 'clutter') OR &quot;class_cue&quot; IS NULL" symbol="2" key="{12b6de09-25fa-4818-b4ba-f1145367e3bd}" label="Other suspect"/>
      <rule filter="&quot;class_cue&quot; = 'clutter'" checkstate="0" symbol="3" key="{2e3064d8-85af-4c96-8037-00c3d17c3378}" label="Clutter"/>
    </rules>
    <symbols>
      <symbol force_rhr="0" type="marker" name="0" clip_to_extent="1" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" locked="0" pass="0">
          <Option type="Map">
            <Option type="QString" name="angle" value="0"/>
            <Option type="QString" name="cap_style" value="square"/>
            <Option type="QString" name="color" value="227,26,28,255"/>
            <Option type="QString" name="horizontal_anchor_point" value="1"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="name" value="triangle"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="35,35,35,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.3"/>
            <Option type="QString" name="outline_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="scale_method" value="diameter"/>
            <Option type="QString" name="size" value="5"/>
            <Option type="QString" name="size_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="size_unit" value="MM"/>
            <Option type="QString" name="vertical_anchor_point" value="1"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="227,26,28,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="triangle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="35,35,35,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="5" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol force_rhr="0" type="marker" name="1" clip_to_extent="1" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" locked="0" pass="0">
          <Option type="Map">
            <Option type="QString" name="angle" value="0"/>
            <Option type="QString" name="cap_style" value="square"/>
            <Option type="QString" name="color" value="227,26,28,255"/>
            <Option type="QString" name="horizontal_anchor_point" value="1"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="name" value="triangle"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="35,35,35,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.3"/>
            <Option type="QString" name="outline_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="scale_method" value="diameter"/>
            <Option type="QString" name="size" value="4"/>
            <Option type="QString" name="size_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="size_unit" value="MM"/>
            <Option type="QString" name="vertical_anchor_point" value="1"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="227,26,28,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="triangle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="35,35,35,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="4" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol force_rhr="0" type="marker" name="2" clip_to_extent="1" alpha="0.6">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" locked="0" pass="0">
          <Option type="Map">
            <Option type="QString" name="angle" value="0"/>
            <Option type="QString" name="cap_style" value="square"/>
            <Option type="QString" name="color" value="255,127,0,255"/>
            <Option type="QString" name="horizontal_anchor_point" value="1"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="name" value="circle"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="90,90,90,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.3"/>
            <Option type="QString" name="outline_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="scale_method" value="diameter"/>
            <Option type="QString" name="size" value="2.4"/>
            <Option type="QString" name="size_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="size_unit" value="MM"/>
            <Option type="QString" name="vertical_anchor_point" value="1"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="255,127,0,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="circle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="90,90,90,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="2.4" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol force_rhr="0" type="marker" name="3" clip_to_extent="1" alpha="0.6">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" locked="0" pass="0">
          <Option type="Map">
            <Option type="QString" name="angle" value="0"/>
            <Option type="QString" name="cap_style" value="square"/>
            <Option type="QString" name="color" value="150,150,150,255"/>
            <Option type="QString" name="horizontal_anchor_point" value="1"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="name" value="circle"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="90,90,90,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.3"/>
            <Option type="QString" name="outline_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="scale_method" value="diameter"/>
            <Option type="QString" name="size" value="2"/>
            <Option type="QString" name="size_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="size_unit" value="MM"/>
            <Option type="QString" name="vertical_anchor_point" value="1"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="150,150,150,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="circle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="90,90,90,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="2" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <orderby>
      <orderByClause asc="0" nullsFirst="1">coalesce(attribute('priority'), 1000000 * (CASE WHEN "class_cue" = 'at_mine' THEN 0 WHEN "class_cue" = 'ap_mine' THEN 1 WHEN "class_cue" = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs("contrast_day_k"), abs("contrast_night_k"))))</orderByClause>
    </orderby>
  </renderer-v2>
  <labeling type="rule-based">
    <rules key="{b20d6f79-206e-4407-8b39-b81ddd1856e7}">
      <rule filter="&quot;class_cue&quot; IN ('at_mine', 'ap_mine')" description="Mine indications" key="{6f31a92a-ece0-4916-b231-c398a5270800}">
        <settings calloutType="simple">
          <text-style blendMode="0" fontLetterSpacing="0" fontSize="9" fieldName="short_id" fontWeight="75" textOrientation="horizontal" isExpression="0" previewBkgrdColor="255,255,255,255" fontSizeMapUnitScale="3x:0,0,0,0,0,0" textOpacity="1" fontWordSpacing="0" fontFamily="DejaVu Sans" textColor="120,0,0,255" multilineHeight="1" legendString="Aa" fontUnderline="0" fontKerning="1" allowHtml="0" useSubstitutions="0" namedStyle="" fontItalic="0" fontStrikeout="0" capitalization="0" fontSizeUnit="Point">
            <families/>
            <text-buffer bufferBlendMode="0" bufferSizeMapUnitScale="3x:0,0,0,0,0,0" bufferNoFill="1" bufferSize="0.80000000000000004" bufferColor="255,255,255,255" bufferDraw="1" bufferJoinStyle="128" bufferSizeUnits="MM" bufferOpacity="1"/>
            <text-mask maskJoinStyle="128" maskType="0" maskedSymbolLayers="" maskSizeUnits="MM" maskSize="1.5" maskEnabled="0" maskOpacity="1" maskSizeMapUnitScale="3x:0,0,0,0,0,0"/>
            <background shapeJoinStyle="64" shapeRadiiX="0" shapeSizeMapUnitScale="3x:0,0,0,0,0,0" shapeDraw="0" shapeSizeUnit="MM" shapeSVGFile="" shapeOpacity="1" shapeBlendMode="0" shapeRotation="0" shapeOffsetX="0" shapeType="0" shapeFillColor="255,255,255,255" shapeRadiiY="0" shapeSizeX="0" shapeBorderWidthMapUnitScale="3x:0,0,0,0,0,0" shapeOffsetY="0" shapeOffsetUnit="MM" shapeBorderColor="128,128,128,255" shapeRadiiUnit="MM" shapeSizeType="0" shapeRotationType="0" shapeOffsetMapUnitScale="3x:0,0,0,0,0,0" shapeBorderWidthUnit="MM" shapeBorderWidth="0" shapeSizeY="0" shapeRadiiMapUnitScale="3x:0,0,0,0,0,0">
              <symbol force_rhr="0" type="fill" name="fillSymbol" clip_to_extent="1" alpha="1">
                <data_defined_properties>
                  <Option type="Map">
                    <Option type="QString" name="name" value=""/>
                    <Option name="properties"/>
                    <Option type="QString" name="type" value="collection"/>
                  </Option>
                </data_defined_properties>
                <layer enabled="1" class="SimpleFill" locked="0" pass="0">
                  <Option type="Map">
                    <Option type="QString" name="border_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
                    <Option type="QString" name="color" value="255,255,255,255"/>
                    <Option type="QString" name="joinstyle" value="bevel"/>
                    <Option type="QString" name="offset" value="0,0"/>
                    <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
                    <Option type="QString" name="offset_unit" value="MM"/>
                    <Option type="QString" name="outline_color" value="128,128,128,255"/>
                    <Option type="QString" name="outline_style" value="no"/>
                    <Option type="QString" name="outline_width" value="0"/>
                    <Option type="QString" name="outline_width_unit" value="MM"/>
                    <Option type="QString" name="style" value="solid"/>
                  </Option>
                  <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
                  <prop v="255,255,255,255" k="color"/>
                  <prop v="bevel" k="joinstyle"/>
                  <prop v="0,0" k="offset"/>
                  <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
                  <prop v="MM" k="offset_unit"/>
                  <prop v="128,128,128,255" k="outline_color"/>
                  <prop v="no" k="outline_style"/>
                  <prop v="0" k="outline_width"/>
                  <prop v="MM" k="outline_width_unit"/>
                  <prop v="solid" k="style"/>
                  <data_defined_properties>
                    <Option type="Map">
                      <Option type="QString" name="name" value=""/>
                      <Option name="properties"/>
                      <Option type="QString" name="type" value="collection"/>
                    </Option>
                  </data_defined_properties>
                </layer>
              </symbol>
            </background>
            <shadow shadowOffsetDist="1" shadowColor="0,0,0,255" shadowOffsetMapUnitScale="3x:0,0,0,0,0,0" shadowOpacity="0.69999999999999996" shadowRadiusUnit="MM" shadowRadiusMapUnitScale="3x:0,0,0,0,0,0" shadowDraw="0" shadowScale="100" shadowOffsetUnit="MM" shadowBlendMode="6" shadowRadiusAlphaOnly="0" shadowUnder="0" shadowOffsetAngle="135" shadowOffsetGlobal="1" shadowRadius="1.5"/>
            <dd_properties>
              <Option type="Map">
                <Option type="QString" name="name" value=""/>
                <Option name="properties"/>
                <Option type="QString" name="type" value="collection"/>
              </Option>
            </dd_properties>
            <substitutions/>
          </text-style>
          <text-format useMaxLineLengthForAutoWrap="1" wrapChar="" autoWrapLength="0" placeDirectionSymbol="0" rightDirectionSymbol=">" reverseDirectionSymbol="0" addDirectionSymbol="0" multilineAlign="3" leftDirectionSymbol="&lt;" decimals="3" plussign="0" formatNumbers="0"/>
          <placement distUnits="MM" geometryGeneratorType="PointGeometry" overrunDistanceMapUnitScale="3x:0,0,0,0,0,0" lineAnchorType="0" lineAnchorClipping="0" quadOffset="4" repeatDistance="0" distMapUnitScale="3x:0,0,0,0,0,0" geometryGeneratorEnabled="0" labelOffsetMapUnitScale="3x:0,0,0,0,0,0" maxCurvedCharAngleIn="25" placement="6" rotationUnit="AngleDegrees" repeatDistanceMapUnitScale="3x:0,0,0,0,0,0" placementFlags="10" lineAnchorPercent="0.5" rotationAngle="0" fitInPolygonOnly="0" dist="1" xOffset="0" centroidWhole="0" preserveRotation="1" yOffset="0" overrunDistance="0" overrunDistanceUnit="MM" layerType="UnknownGeometry" offsetUnits="MM" polygonPlacementFlags="2" maxCurvedCharAngleOut="-25" priority="9" centroidInside="0" geometryGenerator="" offsetType="0" predefinedPositionOrder="TR,TL,BR,BL,R,L,TSR,BSR" repeatDistanceUnits="MM"/>
          <rendering scaleMin="0" displayAll="0" limitNumLabels="0" minFeatureSize="0" scaleMax="0" labelPerPart="0" obstacleFactor="1" drawLabels="1" upsidedownLabels="0" fontMaxPixelSize="10000" mergeLines="0" scaleVisibility="0" maxNumLabels="2000" fontMinPixelSize="0" fontLimitPixelSize="0" unplacedVisibility="0" zIndex="0" obstacle="1" obstacleType="1"/>
          <dd_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </dd_properties>
          <callout type="simple">
            <Option type="Map">
              <Option type="QString" name="anchorPoint" value="pole_of_inaccessibility"/>
              <Option type="int" name="blendMode" value="0"/>
              <Option type="Map" name="ddProperties">
                <Option type="QString" name="name" value=""/>
                <Option name="properties"/>
                <Option type="QString" name="type" value="collection"/>
              </Option>
              <Option type="bool" name="drawToAllParts" value="false"/>
              <Option type="QString" name="enabled" value="0"/>
              <Option type="QString" name="labelAnchorPoint" value="point_on_exterior"/>
              <Option type="QString" name="lineSymbol" value="&lt;symbol force_rhr=&quot;0&quot; type=&quot;line&quot; name=&quot;symbol&quot; clip_to_extent=&quot;1&quot; alpha=&quot;1&quot;>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option type=&quot;QString&quot; name=&quot;name&quot; value=&quot;&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;type&quot; value=&quot;collection&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;layer enabled=&quot;1&quot; class=&quot;SimpleLine&quot; locked=&quot;0&quot; pass=&quot;0&quot;>&lt;Option type=&quot;Map&quot;>&lt;Option type=&quot;QString&quot; name=&quot;align_dash_pattern&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;capstyle&quot; value=&quot;square&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;customdash&quot; value=&quot;5;2&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;customdash_map_unit_scale&quot; value=&quot;3x:0,0,0,0,0,0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;customdash_unit&quot; value=&quot;MM&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;dash_pattern_offset&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;dash_pattern_offset_map_unit_scale&quot; value=&quot;3x:0,0,0,0,0,0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;dash_pattern_offset_unit&quot; value=&quot;MM&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;draw_inside_polygon&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;joinstyle&quot; value=&quot;bevel&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;line_color&quot; value=&quot;60,60,60,255&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;line_style&quot; value=&quot;solid&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;line_width&quot; value=&quot;0.3&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;line_width_unit&quot; value=&quot;MM&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;offset&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;offset_map_unit_scale&quot; value=&quot;3x:0,0,0,0,0,0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;offset_unit&quot; value=&quot;MM&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;ring_filter&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;trim_distance_end&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;trim_distance_end_map_unit_scale&quot; value=&quot;3x:0,0,0,0,0,0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;trim_distance_end_unit&quot; value=&quot;MM&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;trim_distance_start&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;trim_distance_start_map_unit_scale&quot; value=&quot;3x:0,0,0,0,0,0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;trim_distance_start_unit&quot; value=&quot;MM&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;tweak_dash_pattern_on_corners&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;use_custom_dash&quot; value=&quot;0&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;width_map_unit_scale&quot; value=&quot;3x:0,0,0,0,0,0&quot;/>&lt;/Option>&lt;prop v=&quot;0&quot; k=&quot;align_dash_pattern&quot;/>&lt;prop v=&quot;square&quot; k=&quot;capstyle&quot;/>&lt;prop v=&quot;5;2&quot; k=&quot;customdash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;customdash_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;customdash_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;dash_pattern_offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;dash_pattern_offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;dash_pattern_offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;draw_inside_polygon&quot;/>&lt;prop v=&quot;bevel&quot; k=&quot;joinstyle&quot;/>&lt;prop v=&quot;60,60,60,255&quot; k=&quot;line_color&quot;/>&lt;prop v=&quot;solid&quot; k=&quot;line_style&quot;/>&lt;prop v=&quot;0.3&quot; k=&quot;line_width&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;line_width_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;ring_filter&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_end&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_end_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_end_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_start&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_start_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_start_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;tweak_dash_pattern_on_corners&quot;/>&lt;prop v=&quot;0&quot; k=&quot;use_custom_dash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;width_map_unit_scale&quot;/>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option type=&quot;QString&quot; name=&quot;name&quot; value=&quot;&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option type=&quot;QString&quot; name=&quot;type&quot; value=&quot;collection&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;/layer>&lt;/symbol>"/>
              <Option type="double" name="minLength" value="0"/>
              <Option type="QString" name="minLengthMapUnitScale" value="3x:0,0,0,0,0,0"/>
              <Option type="QString" name="minLengthUnit" value="MM"/>
              <Option type="double" name="offsetFromAnchor" value="0"/>
              <Option type="QString" name="offsetFromAnchorMapUnitScale" value="3x:0,0,0,0,0,0"/>
              <Option type="QString" name="offsetFromAnchorUnit" value="MM"/>
              <Option type="double" name="offsetFromLabel" value="0"/>
              <Option type="QString" name="offsetFromLabelMapUnitScale" value="3x:0,0,0,0,0,0"/>
              <Option type="QString" name="offsetFromLabelUnit" value="MM"/>
            </Option>
          </callout>
        </settings>
      </rule>
    </rules>
  </labeling>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field name="fid" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="anomaly_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="x" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="y" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lat" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="7"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lon" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="7"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="area_m2" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diameter_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="circularity" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_sigma_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_sigma_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="status" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="polarity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="class_cue" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="confidence" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="n_scans" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_day_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_night_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="fix_quality" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="figure" configurationFlags="None">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field name="contrast_series" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="short_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="likelihood" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="cue_confidence_pct" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias field="fid" index="0" name=""/>
    <alias field="anomaly_id" index="1" name="Suspect id"/>
    <alias field="x" index="2" name="Easting (m, survey UTM)"/>
    <alias field="y" index="3" name="Northing (m, survey UTM)"/>
    <alias field="lat" index="4" name="Latitude (°, WGS84)"/>
    <alias field="lon" index="5" name="Longitude (°, WGS84)"/>
    <alias field="area_m2" index="6" name="Area (m²)"/>
    <alias field="diameter_m" index="7" name="Diameter (m)"/>
    <alias field="circularity" index="8" name="Circularity (0-1)"/>
    <alias field="depth_m" index="9" name="Burial depth (m)"/>
    <alias field="depth_sigma_m" index="10" name="Depth uncertainty, 1σ (m)"/>
    <alias field="diffusivity_m2s" index="11" name="Thermal diffusivity (m²/s)"/>
    <alias field="diffusivity_sigma_m2s" index="12" name="Diffusivity uncertainty, 1σ (m²/s)"/>
    <alias field="status" index="13" name="Characterisation status"/>
    <alias field="polarity" index="14" name="Polarity"/>
    <alias field="class_cue" index="15" name="Class cue"/>
    <alias field="confidence" index="16" name="Class cue confidence (0-1)"/>
    <alias field="n_scans" index="17" name="Scans seen"/>
    <alias field="contrast_day_k" index="18" name="Day contrast (K)"/>
    <alias field="contrast_night_k" index="19" name="Night contrast (K)"/>
    <alias field="fix_quality" index="20" name="GNSS fix quality"/>
    <alias field="figure" index="21" name="Contrast curve"/>
    <alias field="contrast_series" index="22" name="Contrast series (JSON)"/>
    <alias field="short_id" index="23" name="Short id"/>
    <alias field="depth" index="24" name="Burial depth ± 1σ"/>
    <alias field="diffusivity" index="25" name="Thermal diffusivity ± 1σ"/>
    <alias field="likelihood" index="26" name="Mine likelihood"/>
    <alias field="cue_confidence_pct" index="27" name="Class cue confidence"/>
  </aliases>
  <defaults>
    <default field="fid" expression="" applyOnUpdate="0"/>
    <default field="anomaly_id" expression="" applyOnUpdate="0"/>
    <default field="x" expression="" applyOnUpdate="0"/>
    <default field="y" expression="" applyOnUpdate="0"/>
    <default field="lat" expression="" applyOnUpdate="0"/>
    <default field="lon" expression="" applyOnUpdate="0"/>
    <default field="area_m2" expression="" applyOnUpdate="0"/>
    <default field="diameter_m" expression="" applyOnUpdate="0"/>
    <default field="circularity" expression="" applyOnUpdate="0"/>
    <default field="depth_m" expression="" applyOnUpdate="0"/>
    <default field="depth_sigma_m" expression="" applyOnUpdate="0"/>
    <default field="diffusivity_m2s" expression="" applyOnUpdate="0"/>
    <default field="diffusivity_sigma_m2s" expression="" applyOnUpdate="0"/>
    <default field="status" expression="" applyOnUpdate="0"/>
    <default field="polarity" expression="" applyOnUpdate="0"/>
    <default field="class_cue" expression="" applyOnUpdate="0"/>
    <default field="confidence" expression="" applyOnUpdate="0"/>
    <default field="n_scans" expression="" applyOnUpdate="0"/>
    <default field="contrast_day_k" expression="" applyOnUpdate="0"/>
    <default field="contrast_night_k" expression="" applyOnUpdate="0"/>
    <default field="fix_quality" expression="" applyOnUpdate="0"/>
    <default field="figure" expression="" applyOnUpdate="0"/>
    <default field="contrast_series" expression="" applyOnUpdate="0"/>
    <default field="short_id" expression="" applyOnUpdate="0"/>
    <default field="depth" expression="" applyOnUpdate="0"/>
    <default field="diffusivity" expression="" applyOnUpdate="0"/>
    <default field="likelihood" expression="" applyOnUpdate="0"/>
    <default field="cue_confidence_pct" expression="" applyOnUpdate="0"/>
  </defaults>
  <constraints>
    <constraint exp_strength="0" field="fid" constraints="3" notnull_strength="1" unique_strength="1"/>
    <constraint exp_strength="0" field="anomaly_id" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="x" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="y" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="lat" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="lon" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="area_m2" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diameter_m" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="circularity" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="depth_m" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="depth_sigma_m" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diffusivity_m2s" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diffusivity_sigma_m2s" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="status" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="polarity" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="class_cue" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="confidence" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="n_scans" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="contrast_day_k" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="contrast_night_k" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="fix_quality" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="figure" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="contrast_series" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="short_id" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="depth" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diffusivity" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="likelihood" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint exp_strength="0" field="cue_confidence_pct" constraints="0" notnull_strength="0" unique_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint exp="" field="fid" desc=""/>
    <constraint exp="" field="anomaly_id" desc=""/>
    <constraint exp="" field="x" desc=""/>
    <constraint exp="" field="y" desc=""/>
    <constraint exp="" field="lat" desc=""/>
    <constraint exp="" field="lon" desc=""/>
    <constraint exp="" field="area_m2" desc=""/>
    <constraint exp="" field="diameter_m" desc=""/>
    <constraint exp="" field="circularity" desc=""/>
    <constraint exp="" field="depth_m" desc=""/>
    <constraint exp="" field="depth_sigma_m" desc=""/>
    <constraint exp="" field="diffusivity_m2s" desc=""/>
    <constraint exp="" field="diffusivity_sigma_m2s" desc=""/>
    <constraint exp="" field="status" desc=""/>
    <constraint exp="" field="polarity" desc=""/>
    <constraint exp="" field="class_cue" desc=""/>
    <constraint exp="" field="confidence" desc=""/>
    <constraint exp="" field="n_scans" desc=""/>
    <constraint exp="" field="contrast_day_k" desc=""/>
    <constraint exp="" field="contrast_night_k" desc=""/>
    <constraint exp="" field="fix_quality" desc=""/>
    <constraint exp="" field="figure" desc=""/>
    <constraint exp="" field="contrast_series" desc=""/>
    <constraint exp="" field="short_id" desc=""/>
    <constraint exp="" field="depth" desc=""/>
    <constraint exp="" field="diffusivity" desc=""/>
    <constraint exp="" field="likelihood" desc=""/>
    <constraint exp="" field="cue_confidence_pct" desc=""/>
  </constraintExpressions>
  <expressionfields>
    <field type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" precision="0" comment="" length="0" typeName="" name="short_id" subType="0"/>
    <field type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" precision="0" comment="" length="0" typeName="" name="depth" subType="0"/>
    <field type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" precision="0" comment="" length="0" typeName="" name="diffusivity" subType="0"/>
    <field type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" precision="0" comment="" length="0" typeName="" name="likelihood" subType="0"/>
    <field type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" precision="0" comment="" length="0" typeName="" name="cue_confidence_pct" subType="0"/>
  </expressionfields>
  <attributetableconfig sortOrder="0" actionWidgetStyle="dropDown" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))">
    <columns>
      <column type="field" name="fid" hidden="0" width="-1"/>
      <column type="field" name="anomaly_id" hidden="0" width="-1"/>
      <column type="field" name="x" hidden="0" width="-1"/>
      <column type="field" name="y" hidden="0" width="-1"/>
      <column type="field" name="lat" hidden="0" width="-1"/>
      <column type="field" name="lon" hidden="0" width="-1"/>
      <column type="field" name="area_m2" hidden="0" width="-1"/>
      <column type="field" name="diameter_m" hidden="0" width="-1"/>
      <column type="field" name="circularity" hidden="0" width="-1"/>
      <column type="field" name="depth_m" hidden="0" width="-1"/>
      <column type="field" name="depth_sigma_m" hidden="0" width="-1"/>
      <column type="field" name="diffusivity_m2s" hidden="0" width="-1"/>
      <column type="field" name="diffusivity_sigma_m2s" hidden="0" width="-1"/>
      <column type="field" name="status" hidden="0" width="-1"/>
      <column type="field" name="polarity" hidden="0" width="-1"/>
      <column type="field" name="class_cue" hidden="0" width="-1"/>
      <column type="field" name="confidence" hidden="0" width="-1"/>
      <column type="field" name="n_scans" hidden="0" width="-1"/>
      <column type="field" name="contrast_day_k" hidden="0" width="-1"/>
      <column type="field" name="contrast_night_k" hidden="0" width="-1"/>
      <column type="field" name="fix_quality" hidden="0" width="-1"/>
      <column type="field" name="figure" hidden="0" width="-1"/>
      <column type="field" name="contrast_series" hidden="0" width="-1"/>
      <column type="field" name="short_id" hidden="0" width="-1"/>
      <column type="field" name="depth" hidden="0" width="-1"/>
      <column type="field" name="diffusivity" hidden="0" width="-1"/>
      <column type="field" name="likelihood" hidden="0" width="-1"/>
      <column type="field" name="cue_confidence_pct" hidden="0" width="-1"/>
      <column type="actions" hidden="1" width="-1"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer name="Suspect" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Identification" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField index="23" name="short_id" showLabel="1"/>
        <attributeEditorField index="1" name="anomaly_id" showLabel="1"/>
        <attributeEditorField index="15" name="class_cue" showLabel="1"/>
        <attributeEditorField index="26" name="likelihood" showLabel="1"/>
        <attributeEditorField index="27" name="cue_confidence_pct" showLabel="1"/>
        <attributeEditorField index="13" name="status" showLabel="1"/>
        <attributeEditorField index="14" name="polarity" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Burial depth and soil" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField index="24" name="depth" showLabel="1"/>
        <attributeEditorField index="25" name="diffusivity" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Thermal contrast" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField index="18" name="contrast_day_k" showLabel="1"/>
        <attributeEditorField index="19" name="contrast_night_k" showLabel="1"/>
        <attributeEditorField index="17" name="n_scans" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Shape" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField index="7" name="diameter_m" showLabel="1"/>
        <attributeEditorField index="6" name="area_m2" showLabel="1"/>
        <attributeEditorField index="8" name="circularity" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Contrast curve" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Contrast curve" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField index="21" name="figure" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Position" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Position" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField index="2" name="x" showLabel="1"/>
        <attributeEditorField index="3" name="y" showLabel="1"/>
        <attributeEditorField index="4" name="lat" showLabel="1"/>
        <attributeEditorField index="5" name="lon" showLabel="1"/>
        <attributeEditorField index="20" name="fix_quality" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Stored values" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Stored values" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField index="9" name="depth_m" showLabel="1"/>
        <attributeEditorField index="10" name="depth_sigma_m" showLabel="1"/>
        <attributeEditorField index="11" name="diffusivity_m2s" showLabel="1"/>
        <attributeEditorField index="12" name="diffusivity_sigma_m2s" showLabel="1"/>
        <attributeEditorField index="16" name="confidence" showLabel="1"/>
        <attributeEditorField index="22" name="contrast_series" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>0</layerGeometryType>
</qgis>
